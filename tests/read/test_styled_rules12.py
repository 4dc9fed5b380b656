"""Rules found on the styled manuals (session 12), each on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.cases_cells import time_list
from apbot.read.cases_tables import unnumbered
from apbot.read.text import Unit

# a food warmer whose programme chart numbers its rows in a first column, the names next to
# it, and lists each programme's holding times with the standard one in brackets
WARMER = """PROGRAMMES

Each press of PROG goes to the next programme: SOUP, STEW, BABY, GRAVY.

 No.   Programme   Lid    Warm time
 1     SOUP        yes    15 / [30] / 45 / 60 min
 2     STEW        yes    [20] / 40 / 60 min
 3     BABY        no     -
 4     GRAVY       no     kept warm, up to 2 h

Press WARM TIME to step the warm time. Press START to begin.
"""


def test_a_chart_whose_first_column_numbers_its_rows_gives_each_programme_its_times() -> None:
    actions = ["press_prog", "press_warm_time", "press_start"]
    model = read_manual(WARMER, actions).model
    spec = model.variables["warm_time"].model_dump(mode="json")
    assert spec["depends_on"] == "prog"
    assert spec["cases"]["soup"]["ranges"] == [["00:15:00", "01:00:00", 900]]
    assert spec["cases"]["soup"]["initial"] == "00:30:00"
    assert spec["cases"]["stew"]["ranges"] == [["00:20:00", "01:00:00", 1200]]


def test_a_list_of_times_may_mark_its_standard_one_in_brackets() -> None:
    assert time_list("20 / 30 / [40] / 50 / 60 min") == ([1200, 1800, 2400, 3000, 3600], 2400)
    assert time_list("30, 45 or 60 minutes") == ([1800, 2700, 3600], None)
    assert time_list("[20] / [30] / 40 min") is None  # two standards: not such a list


def test_a_chart_printed_as_two_halves_keeps_its_columns() -> None:
    """ "No. | Dish | Weight | No. | Dish | Weight": the numbers lead each half, so dropping the
    first column would shift the right half's columns under the wrong heads."""
    header = ("No.", "Dish", "Weight", "Rack", "No.", "Dish", "Weight")
    cells = ("1", "Chicken pieces", "400-1200 g", "low rack", "4", "Frozen pizza", "200-600 g")
    rows = [Unit(line=3, text=" | ".join(cells), cells=cells, header=header)]
    assert unnumbered(header, rows) == (header, rows)
    single = ("No.", "Dish", "Weight")
    row = Unit(line=3, text="1 | Chicken | 400 g", cells=("1", "Chicken", "400 g"), header=single)
    assert unnumbered(single, [row])[0] == ("Dish", "Weight")  # one half: the numbers go
