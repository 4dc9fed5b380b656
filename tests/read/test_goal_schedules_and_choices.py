"""A curtain motor's daily timer and states, a cabinet's highlighted and confirmed course, a
QUIET switch said silent, and a value's superlative. Small models and manuals written for
these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_phrases import superlatives

BLINDS = """
appliance: {id: blind_9, category: blind_motor, name: "Shade B-9", brand: S}
controls:
  - {id: up_key, kind: button, label: "UP"}
  - {id: down_key, kind: button, label: "DOWN"}
  - {id: set_key, kind: button, label: "SET"}
  - {id: plus_key, kind: button, label: "+"}
  - {id: timer_key, kind: button, label: "CLK"}
  - {id: pace_key, kind: button, label: "PACE"}
variables:
  blind:
    type: discrete
    values: [closed, open]
  open_time:
    type: time
    ranges: [["00:00:00", "23:30:00", 1800]]
    initial: "07:00:00"
    format: "hh:mm"
    wrap: true
  pace:
    type: discrete
    values: [slow, normal, quick]
    initial: normal
  routine:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "CLK"}
actions:
  press_up: {control: up_key}
  press_down: {control: down_key}
  press_set: {control: set_key}
  press_plus: {control: plus_key}
  press_timer: {control: timer_key}
  press_pace: {control: pace_key}
features:
  blind:
    - actions: [press_up, press_down]
      variable: blind
      effect: {press_up: {to: open}, press_down: {to: closed}}
  open_time:
    - {actions: [press_set]}
    - {actions: [press_plus], variable: open_time, effect: next}
  pace:
    - {actions: [press_pace], variable: pace, effect: next}
  routine:
    - {actions: [press_timer], variable: routine, effect: toggle}
"""

BLINDS_MANUAL = """
KEYS
   (5) CLK - switches the weekday routine on or off
"""


def test_a_state_said_with_its_time_is_the_schedule() -> None:
    model = loads_model(BLINDS)
    assert parse_instruction(model, "open at 6:30 in the morning", BLINDS_MANUAL) == {
        "open_time": "06:30:00"
    }
    assert parse_instruction(model, "blind open now", BLINDS_MANUAL) == {"blind": "open"}


def test_a_legend_after_a_dash_and_the_state_said_before() -> None:
    model = loads_model(BLINDS)
    assert parse_instruction(model, "switch on the weekday routine", BLINDS_MANUAL) == {
        "routine": "on"
    }
    assert parse_instruction(model, "enable the routine", BLINDS_MANUAL) == {"routine": "on"}


def test_a_superlative_of_an_end_value() -> None:
    model = loads_model(BLINDS)
    assert parse_instruction(model, "at the slowest pace", BLINDS_MANUAL) == {"pace": "slow"}
    assert parse_instruction(model, "the quickest pace", BLINDS_MANUAL) == {"pace": "quick"}
    assert superlatives("big") == ["bigest", "biggest"]
    assert superlatives("gentle") == ["gentlest"]


CABINET = """
appliance: {id: cab_9, category: clothes_care_cabinet, name: "Steam C-9", brand: S}
controls:
  - {id: knob, kind: knob, label: "COURSE"}
  - {id: push, kind: button, label: "OK"}
  - {id: quiet_key, kind: button, label: "QUIET"}
  - {id: dry_key, kind: button, label: "DRY+"}
variables:
  highlight:
    type: discrete
    values: [air, deep, soft]
  course:
    type: discrete
    values: [air, deep, soft]
  extra_dry:
    type: numeric
    unit: min
    depends_on: course
    wrap: true
    cases:
      air: {ranges: [[0, 30, 15]], initial: 0}
      deep: {ranges: [[0, 60, 30]], initial: 0}
      soft: {ranges: [[0, 30, 15]], initial: 0}
  quiet:
    type: discrete
    values: ["off", "on"]
actions:
  turn_knob: {control: knob, skill: turn_cw}
  press_ok: {control: push}
  press_quiet: {control: quiet_key}
  press_dry: {control: dry_key}
features:
  pick:
    - {actions: [turn_knob], variable: highlight, effect: next}
  confirm:
    - actions: [press_ok]
      variable: course
      effect:
        when: {highlight: air}
        then: {to: air}
        otherwise:
          when: {highlight: deep}
          then: {to: deep}
          otherwise: {to: soft}
  extra_dry:
    - {actions: [press_dry], variable: extra_dry, effect: next}
  quiet:
    - {actions: [press_quiet], variable: quiet, effect: toggle}
"""


def test_the_confirmed_course_is_the_one_meant() -> None:
    model = loads_model(CABINET)
    assert parse_instruction(model, "the deep course") == {"course": "deep"}
