"""Tables drawn with spaces whose rows wrap onto indented lines, and what their cells say."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.text import parse_manual

GRIDDLE = """
SAFETY
Do not touch the plate while it is hot. Keep children away. Never immerse the base in water.
The appliance is not intended to be operated by means of an external timer.

KEYS

Key        What it does                        Note
ON/OFF     Switches the griddle on and
           off.
MAIN       Selects the main plate.             Touch and hold 2 s:
                                               timer of the main plate.
SIDE       Selects the side plate.            Touch and hold 2 s:
                                               timer of the side plate.
+ / −      Change the heat or the timer
           minutes.

USING THE PLATES
Touch MAIN or SIDE, then + or − to change its heat.
Touch and hold MAIN or SIDE to set that plate's timer with + and −, 1 to 60 minutes.

TROUBLESHOOTING
Problem                    Cause                         Remedy
The griddle switches off   A timer ran out.              Switch it on again.
Keys do nothing            Zones deactivate and reset.   Touch MAIN or SIDE first.
"""

ACTIONS = [
    "press_on_off",
    "press_main",
    "hold_main",
    "press_side",
    "hold_side",
    "press_plus",
    "press_minus",
]


def test_a_wrapped_row_keeps_its_text_in_the_cell_it_stands_under() -> None:
    units = parse_manual(GRIDDLE).units
    left = next(u for u in units if u.cells and u.cells[0] == "MAIN")
    assert left.cells == (
        "MAIN",
        "Selects the main plate.",
        "Touch and hold 2 s: timer of the main plate.",
    )
    power = next(u for u in units if u.cells and u.cells[0] == "ON/OFF")
    assert power.cells[1] == "Switches the griddle on and off."


def test_touch_and_hold_then_a_timer_makes_the_hold_that_plates_timer() -> None:
    model = read_manual(GRIDDLE, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    held = next(f for f in model.features.values() if f[0].actions == ["hold_main"])
    assert held[1].variable == "main_timer"
    assert set(held[1].actions) == {"press_plus", "press_minus"}


def test_on_off_wording_under_troubleshooting_makes_no_toggle() -> None:
    model = read_manual(GRIDDLE, ACTIONS).model
    touched = next(f for f in model.features.values() if f[0].actions == ["press_main"])
    assert touched[0].effect != "toggle"


CHART = """
4 PROGRAMME CHART

Programme    Max. load   Temperature     Description
             (kg)        advised
-----------  ----------  --------------  ---------------------------
Daily        5           30 – 60 °C      Everyday laundry.
Express 20'  2           20 – 40 °C      Lightly soiled, 20 minutes.
Duvet        2           40 °C           One duvet.
"""


def test_a_wrapped_header_line_and_a_dashed_rule_are_no_rows() -> None:
    units = parse_manual(CHART).units
    rows = [u.cells[0] for u in units if u.cells and u.header]
    assert rows == ["Daily", "Express 20'", "Duvet"]
    header = next(u for u in units if u.cells and not u.header)
    assert header.cells[1] == "Max. load (kg)"


def test_a_minute_mark_after_a_programme_number_is_not_part_of_its_name() -> None:
    actions = ["turn_programme_cw", "turn_programme_ccw"]
    model = read_manual(CHART, actions).model
    assert model.variables["programme"].values == ["daily", "express 20", "duvet"]
