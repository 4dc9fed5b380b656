"""Charts whose cells are marks (●, ○, ✓, ✗) explained by a legend line above the chart.

A PDF-flattened chart row ("Linen   60   ●   ●") must keep its marks in their columns, and a
mark is read through the chart's own legend: "● = starts ON" gives a default, "✗ = not
offered" a programme without the option.
"""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.marks_legend import legend_meanings, read_mark
from apbot.read.text import parse_manual

LAUNDRY = """
SAFETY
Keep children away from the door glass while washing. Unplug before cleaning.

PANEL
The CYCLE selector chooses the cycle. SOAK and EXTRA RINSE are buttons: each press turns
the option on or off. START begins the wash.

CYCLE CHART

  ● = option can be chosen      – = option not possible

  Cycle        Temp. (°C)    SOAK     EXTRA RINSE
  ----------   -----------   ------   -----------
  Linen        60            ●        ●
  Denim        40            ●        ●
  Silk         30            –        ●
  Drain        —             –        –

Turn CYCLE to choose Linen, Denim, Silk or Drain.
"""

ACTIONS = ["turn_cycle", "press_soak", "press_extra_rinse", "press_start"]

GRILL = """
PRESETS

  ● = turner reminder starts ON      ○ = turner reminder starts OFF

  Preset (picture)     Turner     Good for
  ------------------   --------   -------------------
  BURGER (bun)         ●          patties, chops
  SALMON (fish         ○          fillets, steaks
  outline)
  TOAST (slice)        ○          sandwiches
  WINGS                ●          chicken wings, legs

Touch a preset pad (BURGER, SALMON, TOAST, WINGS) to choose it. TURNER turns the
reminder on or off; START begins.
"""


def test_a_legend_line_tells_what_each_mark_means() -> None:
    assert legend_meanings("  ✓ = can be set    ✗ = not available    [ ] = standard") == {
        "✓": "yes",
        "✗": "no",
    }
    assert legend_meanings(" ●  step included      ○  step left out") == {"●": "yes", "○": "no"}
    assert legend_meanings("  ● = bell starts ON      ○ = bell starts OFF") == {
        "●": "on",
        "○": "off",
    }
    assert read_mark("✗ (DELAY --)", {"✗": "no"}) == "no (DELAY --)"


def test_marks_stay_in_their_columns_of_a_flattened_chart() -> None:
    rows = [u.cells for u in parse_manual(LAUNDRY).units if u.cells and u.header]
    assert ("Linen", "60", "●", "●") in rows
    assert ("Silk", "30", "–", "●") in rows


def test_an_option_column_of_marks_says_which_cycles_allow_the_option() -> None:
    model = read_manual(LAUNDRY, ACTIONS).model
    soak = model.variables["soak"]
    assert soak.depends_on == "cycle"
    assert set(soak.cases) == {"linen", "denim"}


def test_a_mark_the_legend_calls_on_or_off_is_each_presets_default() -> None:
    model = read_manual(
        GRILL,
        [
            "press_burger",
            "press_salmon",
            "press_toast",
            "press_wings",
            "press_turner",
            "press_start",
        ],
    ).model
    turner = model.variables["turner"]
    assert turner.depends_on
    assert turner.cases["burger"].initial == "on"
    assert turner.cases["salmon"].initial == "off"
    assert turner.cases["toast"].initial == "off"


def test_an_ellipsis_between_two_amounts_spans_a_range_but_not_in_a_list() -> None:
    from apbot.read.values import find_ranges

    assert [(r.low, r.high, r.unit) for r in find_ranges("2 min … 45 min")] == [(2, 45, "min")]
    assert [(r.low, r.high) for r in find_ranges("(warm air, 40 … 70 °C)")] == [(40, 70)]
    assert find_ranges("steps of 5: 10, 15, 20 … 60 °C") == []
    assert find_ranges("then the digits 1 … 9") == []
