"""Set14's reader rules, each on short manuals of other appliances written for the test: a
step said with the key as subject, ratios as single values, arrows fused to a symbol, a two-key
hold of a key only ever held, legend items run together, the digit keys in a key list, a key
that opens a named setting, a sentence that says "it" of that setting, seconds typed as a
number."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.read import read_manual
from apbot.read.actions import parse_actions
from apbot.read.evidence_lists import own_legend_items
from apbot.read.value_lists import cell_list, find_list
from apbot.read.value_steps import find_step


def test_a_key_named_as_the_subject_gives_the_step_without_a_unit() -> None:
    assert find_step("SPEED ▲ raises the speed by 1, SPEED ▼ lowers it by 1.") == (1.0, "")
    assert find_step("VOL UP increases the volume by 2.") == (2.0, "")
    assert find_step("Hold VOL UP to change it by 10.") is None  # a hold's fast steps
    assert find_step("The pump raises the pressure by 3.") is None  # no key: no press


def test_ratios_in_a_cell_are_single_values() -> None:
    assert cell_list("4/3, 1/1, 21/9") == ["4/3", "1/1", "21/9"]
    assert cell_list("400 / 800 / 1200 rpm") is not None  # spaced slashes still part a list


def test_an_arrow_fused_to_a_word_is_a_symbol_in_a_spaced_cycle() -> None:
    found = find_list("Press VENT: →IN INTAKE → OUT→ EXHAUST → OFF")
    assert found == (["INTAKE", "EXHAUST", "OFF"], "arrows")
    found = find_list("The FAN key goes round: →OUT EXTRACT → IN→ SUPPLY → MIXED")
    assert found is not None and found[0] == ["EXTRACT", "SUPPLY", "MIXED"]


def test_a_two_key_hold_may_name_a_key_only_ever_held() -> None:
    infos = parse_actions(["press_zone", "hold_pair", "hold_pair_zone"])
    assert infos[2].controls == ("pair", "zone")
    infos = parse_actions(["hold_reset", "press_light", "hold_reset_light"])
    assert infos[2].controls == ("reset", "light")


def test_a_list_in_another_legend_item_is_not_the_keys() -> None:
    text = (
        "[A]  Top line: IDLE (open), SHUT FRONT, SHUT BACK or SHUT ALL. [B]  Symbol BELL: the "
        "bell sound is on. [C]  Lower line: the zone."
    )
    assert own_legend_items(text, ["BELL"]).strip() == "[B]  Symbol BELL: the bell sound is on."
    assert own_legend_items("Press BELL: IDLE, SHUT or ALL.", ["BELL"]).startswith("Press")


DELAY = """
## Keys

| Key | Use |
|---|---|
| 0-9 | digits for the code and the exit delay |
| * | opens the exit-delay setting |
| # | ends the setting |

## Exit delay

The exit delay is the time you have to leave after arming. It can be set from 20 to 60
seconds, in steps of 10 seconds.

1. Press *. The line shows EXIT 30.
2. Type the new delay in seconds, e.g. 4 then 0 for 40 seconds.
3. Press #.
"""


def test_a_key_that_opens_a_named_setting_sets_that_setting() -> None:
    digits = [f"press_{d}" for d in range(10)]
    model = read_manual(DELAY, [*digits, "press_star", "press_hash"]).model
    spec = model.variables["exit_delay"]
    assert spec.type == "numeric"
    assert {str(v) for v in all_values(spec)} >= {"20", "40", "60"}
    assert "25" not in {str(v) for v in all_values(spec)}
