"""Keys a manual names by their icon: the legend's name stands where the icon is written."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.labels import find_labels
from apbot.read.text import parse_manual
from apbot.read.text_chars import _KEEP
from apbot.read.text_icons import name_icons

FAN_HEATER = """# Bathroom fan heater

## The panel

The keys show pictures only; this guide calls each key by the name below.

  Icon    What it shows        Name in this guide   What it does
  ------  -------------------  -------------------  ------------------------------
  ⌘       four loops           heat key             Heater on / off.
  🌙      crescent moon        night key            Night light on / off.
  ♨       steam rising         warmer key           One step warmer.

## Using it

Touch ⌘ to switch the heater on; the lamp lights. Touch ⌘ again to switch it off.
Touch the crescent moon for the night light. Touch 🌙 again to switch it off.
"""


def _texts(manual: str) -> list[str]:
    return [u.text for u in parse_manual(manual).units]


def test_legend_rows_stay_apart_with_the_guide_name_in_front() -> None:
    rows = [u.cells for u in parse_manual(FAN_HEATER).units if len(u.cells) == 4]
    assert [r[0] for r in rows[1:]] == ["HEAT", "NIGHT", "WARMER"]
    assert [r[2] for r in rows[1:]] == ["heat key", "night key", "warmer key"]


def test_steps_name_the_key_for_its_icon_and_its_description() -> None:
    texts = _texts(FAN_HEATER)
    assert "Touch HEAT again to switch it off." in texts
    assert "Touch NIGHT again to switch it off." in texts
    assert "Touch the NIGHT key for the night light." in texts


def test_the_action_finds_the_steps_that_show_only_its_icon() -> None:
    manual = parse_manual(FAN_HEATER)
    said = {manual.units[i].text for i in find_labels(manual, ["night"])["night"].mentions}
    assert "Touch NIGHT again to switch it off." in said


def test_no_legend_no_name_invented() -> None:
    texts = _texts("Touch 🌙 for the night light. The ⌘ heat key warms the room.\n")
    assert texts[0] == "Touch   for the night light."
    assert "HEAT" not in " ".join(texts) and "NIGHT" not in " ".join(texts)


def test_a_legend_of_marks_that_are_no_keys_is_left_alone() -> None:
    chart = "  ◆  factory setting\n  ●  possible\n\nTouch ◆ for details.\n"
    assert "FACTORY" not in " ".join(_texts(chart))


def test_a_warning_sign_before_a_sentence_names_no_key() -> None:
    texts = _texts("  ⚠  Caution      touch the power key\n\nTouch ⚠ now.\n")
    assert "POWER" not in " ".join(texts)


def test_a_legend_s_description_said_of_a_lamp_stays_a_lamp() -> None:
    text = (
        "| Icon | Look | Name     | Function           |\n"
        "|------|------|----------|--------------------|\n"
        "| ☀    | sun  | WARM key | warm mist on / off |\n"
        "\n"
        "The sun lights while the water heats. Touch the sun to switch warm mist on.\n"
    )
    named = name_icons(text, _KEEP)
    assert "The sun lights while the water heats" in named
    assert "Touch the WARM key to switch" in named


# a plate warmer whose mode lamps carry a picture before each mode's name
PLATE_WARMER = """# Plate warmer PW-1

Lamps: ☀ sun symbol = HOT, ◐ half sun = WARM, ❄ snowflake = KEEP.

| Key | Function |
|---|---|
| POWER | Switches the warmer on and off. |
| MODE | Next mode: ☀ HOT → ◐ WARM → ❄ KEEP → ☀ HOT … |
"""


def test_a_picture_printed_before_a_value_name_is_no_part_of_the_name() -> None:
    model = read_manual(PLATE_WARMER, ["press_power", "press_mode"]).model
    assert model.variables["mode"].values == ["hot", "warm", "keep"], model.variables["mode"]
