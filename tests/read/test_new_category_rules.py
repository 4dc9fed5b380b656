"""Rules from the new-category development set (benchmarks/data/newcats), each on a small manual
of our own."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual

# a yoghurt maker whose chart's rows wrap onto two lines, with a per-row step column and the
# styles printed with spaces between them
CHURN = """
## Keys
- **PROGRAM** — Each press moves on: PLAIN → GREEK → SKYR → back to PLAIN.
- **STYLE** — Each press: MILD → TANGY → SOUR → MILD.
- **TIME +** / **TIME -** — Change the time by 30 minutes.
- **START** — Starts.

Times: 4 to 12 hours.

## Chart

 Program   Use                     Styles        Standard   Time
                                   available     time       step
 -------   ---------------------   -----------   --------   ------
 PLAIN     whole milk, cream       MILD TANGY    8 h        30 min
           or skimmed milk
 GREEK     strained after          MILD TANGY    10 h       30 min
           the cycle
 SKYR      skimmed milk only       TANGY SOUR    12 h       30 min
"""


def test_a_chart_with_wrapped_rows_is_one_table_whose_step_column_gives_no_values() -> None:
    actions = ["press_program", "press_style", "press_time_up", "press_time_down", "press_start"]
    model = read_manual(CHURN, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    style = model.variables["style"]
    assert style.depends_on == "program"
    assert style.cases["plain"].values == ["mild", "tangy"]
    assert style.cases["skyr"].values == ["tangy", "sour"]
    time = model.variables["time"]
    assert time.depends_on is None  # the step column is no list of times
