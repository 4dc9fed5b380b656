"""Durations that name no setting of a read belief: "every two hours" (how often) is no sleep
period's LENGTH, and "three minutes" is never a time of day. Checked on a pond pump controller
written for these tests (its manual gave a quiet period's start and length, not its cleaning
interval)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

POND = """
appliance: {id: pond_1, category: pond_pump, name: "Briola PP-3", brand: B}
controls:
  - {id: quiet_button, kind: button, label: "QUIET"}
  - {id: up_button, kind: button, label: "UP"}
  - {id: down_button, kind: button, label: "DOWN"}
variables:
  quiet:
    type: discrete
    values: ["off", "on"]
  quiet_start_time:
    type: time
    ranges: [["00:00:00", "23:45:00", 900]]
    format: "hh:mm"
    wrap: true
  quiet_length:
    type: numeric
    unit: h
    ranges: [[1, 10, 1]]
actions:
  press_quiet: {control: quiet_button}
  hold_quiet: {control: quiet_button, skill: hold, seconds: 3}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  quiet:
    - {actions: [press_quiet], variable: quiet, effect: toggle}
  quiet_period:
    - {actions: [hold_quiet]}
    - actions: [press_up, press_down]
      variable: quiet_start_time
      effect: {press_up: next, press_down: prev}
    - {actions: [press_quiet]}
    - actions: [press_up, press_down]
      variable: quiet_length
      effect: {press_up: next, press_down: prev}
"""


def test_every_n_hours_is_no_length() -> None:
    model = loads_model(POND)
    outside: list[str] = []
    goal = parse_instruction(
        model, "Flush the pump every two hours, and quiet on.", outside=outside
    )
    assert "quiet_length" not in goal and goal.get("quiet") == "on"


def test_a_length_said_with_its_name_still_counts() -> None:
    model = loads_model(POND)
    goal = parse_instruction(model, "Quiet from 10 pm for four hours.", outside=[])
    assert goal.get("quiet_length") == 4 and goal.get("quiet_start_time") == "22:00:00"


def test_minutes_are_no_time_of_day() -> None:
    model = loads_model(POND)
    goal = parse_instruction(model, "Pause three minutes after each feed.", outside=[])
    assert "quiet_start_time" not in goal


def test_every_n_hours_is_no_setting_counted_in_hours() -> None:
    model = loads_model(POND.replace("quiet_length", "quiet_hours"))
    goal = parse_instruction(model, "Flush the pump every two hours, and quiet on.", outside=[])
    assert "quiet_hours" not in goal and goal.get("quiet") == "on"
