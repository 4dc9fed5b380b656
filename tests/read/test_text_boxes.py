"""Box and grid tables: a key's name wrapped onto two lines stays one row when the table's
rules close every row."""

from __future__ import annotations

from apbot.read.text import parse_manual

# a kettle's key table drawn as an ASCII grid, a rule under every key, CHILD LOCK on two lines
GRID = """KETTLE K-3 GUIDE

+-----------+------------------------------+
| KEY       | WHAT IT DOES                 |
+-----------+------------------------------+
| POWER     | Switches the kettle on/off.  |
+-----------+------------------------------+
| CHILD     | Hold 3 s to lock or unlock   |
| LOCK      | the keys.                    |
+-----------+------------------------------+
| TEMP      | Steps the temperature.       |
+-----------+------------------------------+
"""

# the same keys with one rule under the header only: every line is a row of its own
OPEN_GRID = """KETTLE K-3 GUIDE

+-----------+------------------------------+
| KEY       | WHAT IT DOES                 |
+-----------+------------------------------+
| POWER     | Switches the kettle on/off.  |
| LOCK      | Locks the keys.              |
| TEMP      | Steps the temperature.       |
+-----------+------------------------------+
"""


def _rows(text: str) -> list[tuple[str, ...]]:
    return [u.cells for u in parse_manual(text).units if u.cells]


def test_a_key_name_wrapped_inside_a_ruled_row_is_one_row() -> None:
    rows = _rows(GRID)
    assert ("CHILD LOCK", "Hold 3 s to lock or unlock the keys.") in rows
    assert [r[0] for r in rows] == ["KEY", "POWER", "CHILD LOCK", "TEMP"]


def test_the_same_box_drawn_with_lines_is_read_alike() -> None:
    boxed = GRID.replace(
        "+-----------+------------------------------+", "├" + "─" * 11 + "┼" + "─" * 30 + "┤"
    ).replace("|", "│")
    lines = boxed.split("\n")
    first = next(i for i, line in enumerate(lines) if line.startswith("├"))
    last = max(i for i, line in enumerate(lines) if line.startswith("├"))
    lines[first] = "┌" + "─" * 11 + "┬" + "─" * 30 + "┐"
    lines[last] = "└" + "─" * 11 + "┴" + "─" * 30 + "┘"
    assert [r[0] for r in _rows("\n".join(lines))] == ["KEY", "POWER", "CHILD LOCK", "TEMP"]


def test_rows_under_a_header_rule_alone_stay_apart() -> None:
    assert [r[0] for r in _rows(OPEN_GRID)] == ["KEY", "POWER", "LOCK", "TEMP"]
