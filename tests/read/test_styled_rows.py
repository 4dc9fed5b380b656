"""Shapes a PDF's text gives a manual: a pipe table ruled with "+" and rows wrapped onto a line
of their own, prose in two columns whose last left line is short, a key's name printed as a
value in another key's cycle, and a chart cell's value bearing the legend's default mark."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.cases_cells import _toggle_cell
from apbot.read.cycle_mentions import named_in_cycle_only
from apbot.read.text import parse_manual
from apbot.read.text_rows import wrapped_cells

GRID = """
WHICH HEAT FOR WHAT

 Level       | Watts        | Good for
 (on the     |              |
 display)    |              |
-------------+--------------+---------------------------
 1 – 2       | 200 – 400    | melting chocolate, keeping
             |              | soup warm
 3 – 4       | 600 – 800    | gentle simmering
"""


def test_a_rule_drawn_with_plus_signs_closes_a_header_written_on_three_lines() -> None:
    rows = [u for u in parse_manual(GRID).units if u.cells]
    assert rows[0].cells == ("Level (on the display)", "Watts", "Good for")
    assert rows[1].header == rows[0].cells
    assert rows[1].cells[2] == "melting chocolate, keeping soup warm"  # the wrapped end joined
    assert [r.cells[0] for r in rows[1:]] == ["1 – 2", "3 – 4"]


def test_a_row_of_its_own_is_not_taken_for_a_wrapped_end() -> None:
    above = ("Cotton", "40", "1200")
    assert wrapped_cells(above, ("", "60", "1000")) is None  # a second row: two cells filled
    assert wrapped_cells(("Quick", "small, lightly", "800"), ("", "soiled loads", "")) == (
        "Quick",
        "small, lightly soiled loads",
        "800",
    )
    assert wrapped_cells(("Eco", "saves water", "800"), ("", "Heavy", "")) is None  # not run on


TWO_COLUMNS = """
THE KEYS

The display sits between the two rows of keys,             LAMP — switches the light in the
which are described here from left to right.                oven on and off at any time, also
SHADE — browning. Each touch gives the next one,            while the programme runs.
LAMP → MID → DEEP → LAMP. The display reads for             GO/STOP — starts the programme; a
example SHADE deep. Default:                                second touch stops it.
MID.                                                        Nothing else responds meanwhile.

Touch GO/STOP to begin.
"""


def test_a_short_last_line_of_the_left_column_is_still_read_as_that_column() -> None:
    texts = [u.text for u in parse_manual(TWO_COLUMNS).units]
    assert "Default: MID." in texts
    assert not any("MID." in t and "Nothing else" in t for t in texts)


def test_a_key_named_only_as_a_value_of_another_keys_cycle_gives_that_key_its_values() -> None:
    text = "Each touch gives the next one, LAMP → MID → DEEP → LAMP."
    assert named_in_cycle_only("LAMP", text)
    assert not named_in_cycle_only("LAMP", "Touch LAMP, then MID → DEEP → MID.")
    assert not named_in_cycle_only("LAMP", "LAMP → MID → DEEP.")  # no cycle: keys in turn
    model = read_manual(TWO_COLUMNS, ["press_shade", "press_lamp", "press_go_stop"]).model
    shade = model.variables["shade"]
    assert list(shade.values) == ["lamp", "mid", "deep"]  # type: ignore[union-attr]


RULED = """
PROGRAMME CHART

  ✓ = can be set    ✗ = not available    [ ] = standard value

  Programme   Cooking time          Delay          Keep warm
  ---------   -------------------   ------------   ---------
  WHITE       automatic  ✗          up to 24:00    ✓
  SOUP        0:30 – 3:00           up to 12:00    ✓
  a  CAKE     0:40 – 1:20           –              –
"""


def test_a_gap_inside_one_run_of_the_rule_does_not_split_the_cell() -> None:
    rows = [u.cells for u in parse_manual(RULED).units if u.cells]
    assert rows[1] == ("WHITE", "automatic ✗", "up to 24:00", "✓")  # no column shifted left
    assert rows[2] == ("SOUP", "0:30 – 3:00", "up to 12:00", "✓")
    assert rows[3][:2] == ("a", "CAKE")  # the lead cell's own gap (a callout) stays


def test_a_chart_cell_saying_not_used_leaves_the_option_out_of_that_programme() -> None:
    assert _toggle_cell("not used") is False
    assert _toggle_cell("✓") is True
    assert _toggle_cell("normal") is None


def test_a_lower_case_row_name_under_another_starts_a_row_of_its_own() -> None:
    # a mode chart whose rows are named in lower case and whose later columns are left blank
    assert wrapped_cells(("eco", "low", "", "", ""), ("boost", "high", "", "", "")) is None
    assert wrapped_cells(("", "black tea,", ""), ("", "green tea", "")) == (
        "",
        "black tea, green tea",
        "",
    )
