"""Rules found on the styled manuals (session 13), each on a small example of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.list_lines import wrapped_list
from apbot.read.text import parse_manual
from apbot.read.value_lists import bare_list


def test_a_lone_dash_between_wide_spaced_marks_is_no_mark() -> None:
    assert bare_list("LOW  –  MEDIUM  –  HIGH  –  TURBO") == ["LOW", "MEDIUM", "HIGH", "TURBO"]


# a fan heater whose knob marks run past the page width onto a second line
HEATER = """2 Controls

The marks round the MODE knob are, clockwise from the left:

  FAN  –  LOW  –  MEDIUM  –  HIGH
  –  ECO 1  –  ECO 2

Each click moves one mark. Press START to begin.
"""


def test_knob_marks_wrapped_onto_a_line_opening_with_the_separator_stay_one_list() -> None:
    manual = parse_manual(HEATER)
    k = next(i for i, u in enumerate(manual.units) if u.text.startswith("FAN"))
    assert wrapped_list(manual, k) == ["FAN", "LOW", "MEDIUM", "HIGH", "ECO 1", "ECO 2"]
    model = read_manual(HEATER, ["turn_mode_cw", "turn_mode_ccw", "press_start"]).model
    values = model.variables["mode"].model_dump(mode="json")["values"]
    assert values == ["fan", "low", "medium", "high", "eco 1", "eco 2"]
