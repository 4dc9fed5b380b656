"""Chart legends and marks read only for what they say (review of the chart-mark rules).

A legend's "on" is a state only when it says how the option starts: "available on this
cycle" or "can be switched on or off" tells which cycles offer it, not that it starts on.
"""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.marks_legend import legend_meanings

STEAMER = """
PANEL
The MENU selector picks a menu. KEEP WARM is a button: each press turns keeping warm
on or off. START begins cooking.

MENU CHART

  ● = keep warm available on this menu      – = not available

  Menu         Time (min)    KEEP WARM
  ----------   -----------   ---------
  Rice         40            ●
  Fish         15            ●
  Eggs         12            –
  Greens       8             –

Turn MENU to choose Rice, Fish, Eggs or Greens.
"""


def test_on_as_a_preposition_or_both_states_is_no_starting_state() -> None:
    assert legend_meanings("  ● = available on this cycle      – = not available") == {
        "●": "yes",
        "–": "no",
    }
    assert legend_meanings("  ✓ = can be switched on or off    ✗ = not possible") == {
        "✓": "yes",
        "✗": "no",
    }
    assert legend_meanings("  ● = starts ON for this menu      ○ = starts OFF") == {
        "●": "on",
        "○": "off",
    }


def test_a_mark_offered_on_a_menu_does_not_start_the_option_on() -> None:
    model = read_manual(STEAMER, ["turn_menu", "press_keep_warm", "press_start"]).model
    warm = model.variables["keep_warm"]
    assert warm.depends_on == "menu"
    assert set(warm.cases) == {"rice", "fish"}
    assert all(case.initial != "on" for case in warm.cases.values())


LAMPS = """
THE DISPLAY

  ●  lamp on: heating      ○  lamp off: standby

PANEL
The MENU selector picks a menu. KEEP WARM is a button: each press turns keeping warm
on or off. START begins cooking.

MENU CHART

  Menu         Time (min)    KEEP WARM
  ----------   -----------   ---------
  Rice         40            ●
  Fish         15            ●
  Eggs         12            –
  Greens       8             –

Turn MENU to choose Rice, Fish, Eggs or Greens.
"""


def test_a_legend_of_another_section_does_not_read_a_charts_marks() -> None:
    model = read_manual(LAMPS, ["turn_menu", "press_keep_warm", "press_start"]).model
    warm = model.variables["keep_warm"]
    assert warm.depends_on == "menu"
    assert set(warm.cases) == {"rice", "fish"}
    assert all(case.initial != "on" for case in warm.cases.values())


def test_an_ellipsis_between_two_kinds_of_amount_spans_nothing() -> None:
    from apbot.read.values import find_ranges

    assert find_ranges("Fish: 20 min … 180 °C") == []  # a time and a heat side by side
    assert [(r.low, r.high, r.unit) for r in find_ranges("250 g … 1.5 kg")] == [(250, 1500, "g")]


def test_a_header_word_broken_at_its_hyphen_stays_a_compound_unless_printed_whole() -> None:
    from apbot.read.text import parse_manual

    chart = """
OPTIONS CHART

  Programme    EXTRA-    PRE-
               RINSE     WASH
  ----------   -------   ------
  Cotton       yes       yes
  Wool         no        no

PREWASH adds a short wash first; EXTRA RINSE adds a rinse.
"""
    heads = {u.header for u in parse_manual(chart).units if u.header}
    assert heads == {("Programme", "EXTRA-RINSE", "PREWASH")}


def test_a_legend_under_the_next_charts_title_is_that_charts() -> None:
    from apbot.read.marks_legend import chart_legend

    lines = [
        "FIRST CHART",
        "",
        "  Menu    KEEP WARM",
        "  Rice    ●",
        "  Eggs    –",
        "",
        "SECOND CHART",
        "",
        "  ● = starts ON      ○ = starts OFF",
        "",
    ]
    assert chart_legend(lines, 3, 4) == {}
    assert chart_legend(lines[:6] + lines[8:], 3, 4) == {"●": "on", "○": "off"}
