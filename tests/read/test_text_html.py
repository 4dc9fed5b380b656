"""HTML tables written by a PDF converter: each <tr> one row of cells at its own line, the
header from <th> cells, so a key legend's rows never run together as one sentence."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a grill's key legend as a vision model wrote it out: one row per line, a header of <th>
ONE_ROW_PER_LINE = """GRILL G-7 — KEYS

<table>
<tr><th>Key</th><th>Function</th></tr>
<tr><td>POWER</td><td>Switch the grill on or off.</td></tr>
<tr><td>SEAR</td><td>Each press steps the sear level: LOW, MID, HIGH.</td></tr>
<tr><td>TIMER</td><td>Sets the time, 1 to 30 minutes in 1 minute steps.</td></tr>
</table>

Clean the plates after use.
"""

# the same legend spread over many lines, with entities, a line break and inline tags
SPREAD = """GRILL G-7 — KEYS

<table class="keys">
  <thead>
    <tr>
      <th>Key</th>
      <th>Function</th>
    </tr>
  </thead>
  <tbody>
    <tr>
      <td><b>POWER</b></td>
      <td>Switch the grill on&nbsp;or off.</td>
    </tr>
    <tr>
      <td>SEAR</td>
      <td>Each press steps the sear level:<br>LOW, MID, HIGH.</td>
    </tr>
  </tbody>
</table>
"""


def _rows(text: str) -> list[tuple[int, tuple[str, ...], tuple[str, ...]]]:
    return [(u.line, u.cells, u.header) for u in parse_manual(text).units if u.cells]


def test_each_row_of_a_one_line_per_row_table_is_a_row_at_its_own_line() -> None:
    rows = _rows(ONE_ROW_PER_LINE)
    assert [r[1][0] for r in rows] == ["Key", "POWER", "SEAR", "TIMER"]
    assert [r[0] for r in rows] == [4, 5, 6, 7]  # the report quotes each row's own line
    assert all(r[2] == ("Key", "Function") for r in rows[1:])
    prose = [u.text for u in parse_manual(ONE_ROW_PER_LINE).units if not u.cells]
    assert "Clean the plates after use." in prose
    assert not any("<" in t for t in prose)  # the tags alone are no text


def test_a_table_spread_over_many_lines_gives_the_same_rows_cleaned() -> None:
    rows = _rows(SPREAD)
    assert [r[1] for r in rows] == [
        ("Key", "Function"),
        ("POWER", "Switch the grill on or off."),
        ("SEAR", "Each press steps the sear level: LOW, MID, HIGH."),
    ]


def test_a_whole_table_on_one_line_and_a_spanned_cell() -> None:
    text = (
        "<table><tr><th>Programme</th><th colspan='2'>Time</th></tr>"
        "<tr><td>Toast</td><td>2</td><td>8 min</td></tr></table>"
    )
    assert [r[1] for r in _rows(text)] == [("Programme", "Time", "Time"), ("Toast", "2", "8 min")]


def test_tags_named_in_running_text_and_an_unclosed_table_lose_no_prose() -> None:
    named = "The export writes a <table> element.\nPress POWER to start."
    assert [u.text for u in parse_manual(named).units] == [
        "The export writes a <table> element.",
        "Press POWER to start.",
    ]
    unclosed = "<table>\n<tr><td>POWER</td><td>On or off.</td></tr>\n\nPress POWER to start."
    units = parse_manual(unclosed).units
    assert [u.cells for u in units if u.cells] == [("POWER", "On or off.")]
    assert "Press POWER to start." in [u.text for u in units]


def test_a_legend_in_html_gives_the_key_its_values() -> None:
    actions = ["press_power", "press_sear", "press_timer"]
    model = read_manual(ONE_ROW_PER_LINE, actions).model
    sear = model.variables["sear"]
    assert [str(x).lower() for x in sear.values] == ["low", "mid", "high"]


def test_text_beside_a_table_on_its_line_is_kept() -> None:
    text = (
        "Keys: <table><tr><th>Key</th><th>Function</th></tr>"
        "<tr><td>START</td><td>Starts heating</td></tr></table> Press START to boil the water.\n"
    )
    units = parse_manual(text).units
    assert [u.text for u in units] == [
        "Keys:",
        "Key | Function",
        "START | Starts heating",
        "Press START to boil the water.",
    ]
    assert {u.line for u in units} == {1}
