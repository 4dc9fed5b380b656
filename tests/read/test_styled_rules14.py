"""A rule found on styled manuals where a key's values went unread: a plain-text manual whose
Title Case page headings were not seen (the safety page's "CAUTION" then held for the whole
manual), on a small manual of our own."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual
from apbot.read.shapes import _cell_key
from apbot.read.text import parse_manual


def _values(model, name: str) -> list[str]:  # type: ignore[no-untyped-def]
    var = model.variables[name]
    assert isinstance(var, DiscreteVariable), var
    return [str(v).lower() for v in var.values]


# a fan heater's manual as text from a PDF: a safety page ending in "CAUTION", a rule, then
# pages headed in Title Case
HEATER = """Safety Precautions

  WARNING
Do not cover the heater.

  CAUTION
Do not touch the grille while it is hot.

                                                     HT-20  2
________________________________________________________________________________

Control Panel
Press HEAT to step through the output: LOW -> MID -> HIGH -> LOW ...
"""


def test_a_title_case_line_heading_a_page_starts_a_section() -> None:
    units = parse_manual(HEATER).units
    heat = next(u for u in units if "HEAT to step" in u.text)
    assert heat.heading == "Control Panel"


def test_a_page_heading_ends_the_safety_section_so_the_keys_values_are_read() -> None:
    model = read_manual(HEATER, ["press_heat"]).model
    assert _values(model, "heat") == ["low", "mid", "high"]


def test_a_lettered_legend_row_names_its_key_without_the_letter() -> None:
    assert _cell_key("(C) SPEED") == "SPEED"
    assert _cell_key("(1) SPEED") == "(1) SPEED"  # (a number is the row's count, read apart)


_RULE = "_" * 80
# a running header "Owner's Manual" heading every page, a procedure going over a page
RUNNING = f"""Owner's Manual
USING THE TIMER
1. Press ON/OFF.
2. Press TIMER to choose the hours: 1H -> 2H -> 4H -> 8H.
{_RULE}
Owner's Manual
3. Press START.
4. The timer lamp lights.
{_RULE}
Owner's Manual
FAN SPEED
Press FAN to step through LOW -> HIGH.
"""


def test_a_title_heading_every_page_alike_is_a_running_header_no_section() -> None:
    units = parse_manual(RUNNING).units
    assert next(u for u in units if u.step == 3).heading == "USING THE TIMER"
    assert next(u for u in units if "Press FAN" in u.text).heading == "FAN SPEED"
    assert not any("Owner's Manual" in u.text for u in units)


# a procedure running over a page break: the page's first line goes on with the sentence
TIMER_OVER_PAGES = """Using the Timer

1. Press TIMER.
2. Set the hours with + and -, for example 8H, then

                                                     HT-20  4
________________________________________________________________________________

Press START
3. The timer lamp lights.
"""


def test_a_page_that_goes_on_with_an_unfinished_sentence_starts_no_section() -> None:
    units = parse_manual(TIMER_OVER_PAGES).units
    start = next(u for u in units if u.text == "Press START")
    assert start.heading != "Press START"
