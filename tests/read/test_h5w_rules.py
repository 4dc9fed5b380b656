"""Ways long manuals write settings that the reader missed (found on the newcats eighth set):
ASCII grid tables, clock ranges stepped in seconds, a push-and-turn knob, a cycle of settings
that shares names with keys, two named settings a key switches between."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.text_boxes import unbox
from apbot.read.values_stepped import find_stepped_pieces

GRID = """
SETTINGS

  The wait depends on the mode:

  +--------+----------------------+--------------+
  | mode   | meaning              | values       |
  +--------+----------------------+--------------+
  | AUTO   | after the cat left,  | 3, 7 min     |
  |        | before cleaning      |              |
  | TIMED  | between cleanings    | 2, 4 h       |
  +--------+----------------------+--------------+
"""


def test_an_ascii_grid_table_is_read_as_a_table() -> None:
    """The "+---+" borders are the table's rules: the first row is its header, and a line whose
    first cell is empty continues the row above."""
    units = [u for u in parse_manual(GRID).units if u.cells]
    assert units[0].cells == ("mode", "meaning", "values")
    assert units[1].header == ("mode", "meaning", "values")
    assert units[1].cells[1] == "after the cat left, before cleaning"
    assert units[2].cells[0] == "TIMED"


def test_a_panel_drawing_boxed_in_ascii_is_left_alone() -> None:
    text = "+-----------------+\n|  [ A ]   [ B ]  |\n+-----------------+\n"
    assert unbox(text) == text  # no column marks: a drawing, not a table


def test_a_clock_range_stepped_in_seconds_is_minutes_and_seconds() -> None:
    pieces = find_stepped_pieces("0:30 to 5:00 | 30 seconds 5:00 to 30:00 | 1 minute")
    assert [(p.low, p.high, p.step) for p in pieces] == [(30, 300, 30), (300, 1800, 60)]
    said = "0:00 to 5:00   in 30-second steps 5:00 to 20:00   in 1-minute steps"
    assert [(p.low, p.high) for p in find_stepped_pieces(said)] == [(0, 300), (300, 1200)]
    hours = find_stepped_pieces("0:30 - 12:00 30 minutes 12:00 - 24:00 1 hour")
    assert [(p.low, p.high) for p in hours] == [(1800, 43200), (43200, 86400)]  # still h:mm


def test_a_clock_past_24_stepped_in_hours_stays_hours() -> None:
    """A long delay ("24:00 to 72:00 in 1-hour steps") is hours, though its clock passes 24."""
    said = "0:00 to 24:00 in 10-minute steps, 24:00 to 72:00 in 1-hour steps"
    pieces = find_stepped_pieces(said)
    assert [(p.low, p.high, p.step) for p in pieces] == [(0, 86400, 600), (86400, 259200, 3600)]


CLEANER = """
CONTROL PANEL

  No.  Key / element   Function
  ---  --------------  ------------------------------------------
  (1)  POWER           Switches the bath on and off.
  (2)  ▲               Raises the bath temperature.
  (3)  ▼               Lowers the bath temperature.
  (4)  TIME knob       Push: open the time setting. Turn: change the time.
  (5)  LEVEL           Output 100 % -> 70 % -> 40 % -> 100 %.
  (6)  START           Starts or stops the bath.

SETTING THE TIME (TIME KNOB)

  1. Push the TIME knob once. The time flashes.
  2. Turn the knob right for a longer time, left for a shorter one.
  3. The time changes in these steps:

       +-------------------+------------------+
       | span              | one click        |
       +-------------------+------------------+
       | 0:30 to 4:00      | 30 seconds       |
       | 4:00 to 20:00     | 1 minute         |
       +-------------------+------------------+

SETTING THE TEMPERATURE

  Press ▲ or ▼ to set the bath temperature, 20 to 60 °C in steps of 5 °C.
"""

CLEANER_ACTIONS = [
    "press_power",
    "press_up",
    "press_down",
    "push_knob",
    "turn_knob_cw",
    "turn_knob_ccw",
    "press_level",
    "press_start",
]


def test_a_push_and_turn_knob_sets_its_own_time() -> None:
    """Pushed, the knob opens the time its sentences name; its own turns then change it (not
    the ▲ / ▼ pair), in the steps of the table the colon introduces."""
    model = read_manual(CLEANER, CLEANER_ACTIONS).model
    feature = next(f for f in model.features.values() if f[0].actions == ["push_knob"])
    var = model.variables[feature[1].variable]
    assert set(feature[1].actions) == {"turn_knob_cw", "turn_knob_ccw"}
    assert var.type == "time"
    assert [tuple(r) for r in var.ranges] == [
        ("00:00:30", "00:04:00", 30),
        ("00:04:00", "00:20:00", 60),
    ]
