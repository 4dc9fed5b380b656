"""Coded values named by a chart drawn with spaces: a description's second line, indented
under its column, does not end the chart; a description that opens with "a name: …" spells
out a short code name (HRC); a number the display shows as a code ("M{value}") is named by the
chart's rows of that code. Small models and charts written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_manual import coded_names

ROWER = """
appliance: {id: rower_1, category: rowing_machine, name: "Oar R-2 rower", brand: O}
controls:
  - {id: prog_key, kind: button, label: "PROG"}
variables:
  program:
    type: discrete
    values: [p1, p2, p3, p4]
    show: {p1: "P1", p2: "P2", p3: "P3", p4: "P4"}
actions:
  press_prog: {control: prog_key}
features:
  program:
    - {actions: [press_prog], variable: program, effect: next}
"""

ROWER_CHART = """
PROGRAMMES

   No.  Name        What the console does
   P1   MANUAL      the same resistance all the time
   P2   PYRAMID     resistance climbs, then falls back
   P3   SPM         strokes per minute: the console keeps your pace at the
                    target you set before the start
   P4   SURPRISE    a different profile each time
"""

CHIME = """
appliance: {id: chime_1, category: door_chime, name: "Ring C-1 chime", brand: R}
controls:
  - {id: tune_key, kind: button, label: "TUNE"}
variables:
  tune:
    type: numeric
    ranges: [[1, 6, 1]]
    wrap: true
    show: "T{value}"
actions:
  press_tune: {control: tune_key}
features:
  tune:
    - {actions: [press_tune], variable: tune, effect: next}
"""

CHIME_CHART = """
The tunes:

  T1   Two-tone          T4   Cathedral bells
  T2   Three-tone        T5   Birdsong
  T3   Harp              T6   Silent (light only)
"""


def test_a_chart_row_continued_on_an_indented_line_goes_on() -> None:
    names = coded_names(loads_model(ROWER), ROWER_CHART)
    assert ("program", "p4", "SURPRISE") in names
    assert ("program", "p3", "strokes per minute") in names  # the code spelt out


def test_a_number_shown_as_a_code_is_named_by_the_chart() -> None:
    model = loads_model(CHIME)
    assert ("tune", 5, "Birdsong") in coded_names(model, CHIME_CHART)
    assert parse_instruction(model, "the cathedral bells please", CHIME_CHART) == {"tune": 4}
    assert parse_instruction(loads_model(ROWER), "the surprise programme", ROWER_CHART) == {
        "program": "p4"
    }
