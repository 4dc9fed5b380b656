"""Ways long manuals write settings that the reader missed (found on the newcats eighth set):
ASCII grid tables, clock ranges stepped in seconds, a push-and-turn knob, a cycle of settings
that shares names with keys, two named settings a key switches between."""

from __future__ import annotations

from apbot.read.text import parse_manual
from apbot.read.text_boxes import unbox

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
