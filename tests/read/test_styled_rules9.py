"""Formats of commercial manuals found on the styled set (ninth round), each on a small manual
of our own."""

from __future__ import annotations

from apbot.read.text import parse_manual

# a chart whose rows go on after the page's footer and a drawn line under it
PAGED = """ACME K2 kettle                                                  page 1
-----------------------------------------------------------------------

HOLD key

Hold times

  Display    Hold time         Presses
  -------    ---------------   -------
  0 min      no hold           none
  15 min     a quarter hour    1 press


ACME K2 kettle                                                  page 2
-----------------------------------------------------------------------

  30 min     half an hour      2 presses
  60 min     one hour          3 presses

Cleaning

Wipe the kettle with a damp cloth.

ACME K2 kettle                                                  page 3
-----------------------------------------------------------------------
"""


def test_a_chart_goes_on_after_the_footer_and_the_drawn_line_of_a_page_break() -> None:
    units = parse_manual(PAGED).units
    rows = [u for u in units if u.header and u.header[0] == "Display"]
    assert [u.cells[0] for u in rows] == ["0 min", "15 min", "30 min", "60 min"], [
        (u.text, u.header) for u in units
    ]
