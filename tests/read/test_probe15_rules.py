"""Rules from probing the reader with short manuals of our own (probe15): each rule on a small
manual written in different words from the probe that found it."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual


def _read(text: str, actions: list[str]) -> dict[str, Any]:
    """The model read, as the YAML a reading writes (the lists and maps a test can compare)."""
    return read_manual(text, actions).model.model_dump(mode="json", exclude_defaults=True)


# a water cooler whose service settings are a code table under a heading naming the menu (N12)
COOLER = """
AquaChill WC-3 Water Cooler

Buttons
ON/OFF, SET, + , -

Service menu
Keep SET pressed for 5 seconds to enter the service menu. Press SET to move to the next code,
+ and - to change it.

| Code | Function         | Values          | Default |
|------|------------------|-----------------|---------|
| A01  | Chill target     | 4 – 12, step 2  | 6       |
| A02  | Night quiet      | 0 = off, 1 = on | 0       |
| A03  | Scale            | C / F           | F       |
"""


def test_a_zero_padded_code_table_under_a_menu_heading_is_a_settings_menu() -> None:
    model = _read(COOLER, ["press_onoff", "press_set", "hold_set", "press_plus", "press_minus"])
    variables = model["variables"]
    chill = variables["chill_target"]
    assert chill["ranges"] == [[4, 12, 2]] and chill["initial"] == 6
    quiet = variables["night_quiet"]
    assert quiet["values"] == ["off", "on"] and quiet["show"] == {"off": "0", "on": "1"}
    assert quiet["initial"] == "off"
    scale = variables["scale"]
    assert scale["values"] == ["c", "f"] and scale["initial"] == "f"
    assert "settings_menu" in model["features"]


# a hand warmer whose power key is named "..._toggle" and whose levels are lamps by place (N4, N15)
WARMER = """
CosyHands HW-2 rechargeable hand warmer

Power
Press the power key to switch the warmer on; hold it to switch off.

Warmth
When the warmer starts, the first LED comes on. Every press of LEVEL moves to the next LED:
the second LED, then the third LED, then the fourth LED. A further press returns to the first.
"""


def test_a_toggle_named_power_key_is_power_and_lamps_by_place_are_levels() -> None:
    model = _read(WARMER, ["power_toggle", "hold_power_toggle", "level_key"])
    assert model["variables"]["power"]["values"] == ["off", "on"]
    level = model["variables"]["level"]
    assert level["type"] == "numeric" and level["ranges"] == [[1, 4, 1]]
    assert level["initial"] == 1
    assert model["features"]["set_level"][0]["effect"] == "next" and level["wrap"]


# a fan heater with only a rocker-style switch named by its kind (N16)
FAN_HEATER = """
BreezeBox FH-1 fan heater

Controls
A switch (OFF / ON) on the side and a FAN button on top.

Use
Put the switch in the ON position, then press FAN to change between low and high.
"""


def test_a_switch_named_only_by_its_kind_and_moved_to_on_is_the_power_switch() -> None:
    model = _read(FAN_HEATER, ["flip_switch", "press_fan"])
    assert "power" in model["variables"]
    assert model["features"]["power"][0]["actions"] == ["flip_switch"]


# a juicer card: two speeds joined by one arrow with a start aside, and a start said of the
# appliance starting at a named value far from the key (N3, U3)
JUICER = """
PressPro J-2 slow juicer

| No. | Key   | What it does                    | Note          |
|-----|-------|---------------------------------|---------------|
| 1   | PULP  | Tap: FINE → COARSE              | (default FINE) |
| 2   | SPEED | Tap to change the speed: LO, MID or HI |        |

Getting started
Plug in and press ON. The juicer begins at speed MID.
"""


def test_two_capital_names_joined_by_one_arrow_are_a_list_and_a_start_aside_is_no_gloss() -> None:
    model = _read(JUICER, ["press_on", "press_pulp", "press_speed"])
    pulp = model["variables"]["pulp"]
    assert pulp["values"] == ["fine", "coarse"]


def test_the_appliance_starting_at_a_named_value_of_a_setting_is_its_start() -> None:
    model = _read(JUICER, ["press_on", "press_pulp", "press_speed"])
    speed = model["variables"]["speed"]
    assert speed["values"] == ["lo", "mid", "hi"] and speed["initial"] == "mid"


# a rice cooker whose quick programme holds its time, said "<mode> has a fixed <setting> of N" (C4)
COOKER = """
GrainMate RC-8 rice cooker

Keys: POWER, MENU, TEMP +, TEMP -, START

MENU steps through WHITE → BROWN → QUICK → STEW.
Press TEMP + or TEMP - to set the cooking temperature from 90 to 110 °C in 5 °C steps.
QUICK has a fixed temperature of 105 °C.
"""


def test_a_mode_that_has_a_fixed_setting_of_a_value_holds_it_in_that_mode() -> None:
    model = _read(COOKER, ["press_power", "press_menu", "temp_up", "temp_down", "press_start"])
    temp = next(v for v in model["variables"].values() if v.get("depends_on"))
    assert temp["cases"]["quick"]["ranges"] == [[105, 105, 1]]
    assert temp["cases"]["white"]["ranges"][0][:2] == [90, 110]


def test_an_action_named_verb_last_or_with_its_hold_length_is_parsed_like_verb_first() -> None:
    from apbot.read.actions import action_info, parse_actions

    infos = {i.name: i for i in parse_actions(["mode_press", "mode_hold_5s", "dial_rotate_ccw"])}
    assert (infos["mode_press"].skill, infos["mode_press"].controls) == ("press", ("mode",))
    assert (infos["mode_hold_5s"].skill, infos["mode_hold_5s"].controls) == ("hold", ("mode",))
    assert infos["dial_rotate_ccw"].skill == "turn_ccw"
    assert action_info("press_30s").controls == ("30s",)  # a key printed 30s, no hold length


def test_an_arrow_key_is_a_stepping_key_and_a_turn_button_is_the_turn_key() -> None:
    from apbot.read.actions import action_info

    assert action_info("arrow_down").controls == ("down",)
    turn = action_info("turn_key")
    assert (turn.skill, turn.controls) == ("press", ("turn",))


# a popcorn maker whose keys are named only in quotes in prose (new probe p21's style)
POPPER = """
PopStar PC-1 popcorn maker

Press the "Power" key to switch the machine on or off.
Press the ‘Batch’ key to choose the batch size: small, medium or large.
The display shows 'Err' when the lid is open.
"""


def test_a_key_named_only_in_quotes_is_read_as_its_printed_name() -> None:
    model = _read(POPPER, ["press_power", "press_batch"])
    assert model["variables"]["batch"]["values"] == ["small", "medium", "large"]
    assert model["variables"]["power"]["values"] == ["off", "on"]


# a neck massager's reference card: the timer told by how often its key is pressed (N11)
MASSAGER = """
KneadEase NM-5 neck massager

## Quick reference

| Press                 | Result                 |
|-----------------------|------------------------|
| SPAN  once            | 5 min                  |
| SPAN  twice           | 15 min                 |
| SPAN  three times     | 25 min                 |
| SPAN  four times      | timer off              |
"""


def test_a_keys_press_count_rows_are_the_values_it_steps_through() -> None:
    model = _read(MASSAGER, ["press_on_off", "press_span"])
    span = model["variables"]["span"]
    assert span["initial"] in ("00:00:00", 0)
    flat = [p[:2] for p in span["ranges"]]
    assert flat[0][0] in ("00:00:00", 0) and flat[-1][1] in ("00:25:00", 25)
