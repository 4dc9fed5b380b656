"""Rules found on the round-10 styled manuals (session 11), each on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.value_lists import bare_list

# a toaster-style grill with a selector knob whose marks are printed as a one-row table after a
# sentence ending in a colon, and whose end stops are said a few lines after the knob's name
GRILL = """CONTROLS

1  SELECTOR knob
The marks printed round the knob, from the left stop:

 OFF  |  GRILL  |  TOP HEAT  |  FAN GRILL  |  DEFROST
 (none) (zigzag) (one bar) (fan and zigzag) (snowflake)

The knob has a stop at each end and cannot go all the way round.

2  LAMP
Press to switch the lamp on; press again to switch it off.
"""

# a steamer whose mode key is explained by a row of names, each with how many presses reach it
STEAMER = """MODES

Each press of MODE goes to the next mode.
How many presses of MODE after switching on:
 QUICK 0 | NORMAL 1 | EXTRA 2 | KEEP 3

Press START to begin.
"""


def test_a_lone_table_row_after_a_colon_is_the_knobs_marks() -> None:
    model = read_manual(GRILL, ["turn_selector_cw", "turn_selector_ccw", "press_lamp"]).model
    spec = model.variables["selector"].model_dump(mode="json")
    assert spec["values"] == ["off", "grill", "top heat", "fan grill", "defrost"]


def test_a_knobs_end_stops_said_after_its_marks_are_its_own() -> None:
    model = read_manual(GRILL, ["turn_selector_cw", "turn_selector_ccw", "press_lamp"]).model
    assert model.variables["selector"].model_dump(mode="json")["wrap"] is False


def test_names_with_their_press_counts_are_the_names() -> None:
    assert bare_list("QUICK 0 | NORMAL 1 | EXTRA 2 | KEEP 3") == [
        "QUICK",
        "NORMAL",
        "EXTRA",
        "KEEP",
    ]
    assert bare_list("WARM 0 · BAKE 1 · CONV BAKE 2") == ["WARM", "BAKE", "CONV BAKE"]
    # codes whose digits do not count the presses one by one stay whole
    assert bare_list("P 1 · P 3 · P 5") == ["P 1", "P 3", "P 5"]
    model = read_manual(STEAMER, ["press_mode", "press_start"]).model
    assert model.variables["mode"].model_dump(mode="json")["values"] == [
        "quick",
        "normal",
        "extra",
        "keep",
    ]
