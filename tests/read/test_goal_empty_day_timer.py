"""A wrapping 00:00-23:xx time setting the model says starts at 00:00 counts hours from empty
(a keep-warm timer, a switch-off timer), so "for 5 hours" sets it; only one that starts at a
time of day (or whose start is not stated) is a time of day something happens at. Checked on a
food warmer written for this test."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

WARMER = """
appliance: {id: warmer_1, category: food_warmer, name: "Tepida warmer", brand: T}
controls:
  - {id: warm_button, kind: button, label: "HOLD"}
  - {id: off_button, kind: button, label: "AUTO OFF"}
  - {id: up_button, kind: button, label: "+"}
variables:
  hold_hours:
    type: time
    ranges: [["00:00:00", "23:00:00", 3600]]
    initial: "00:00:00"
    format: "hh:mm"
    wrap: true
  auto_off:
    type: time
    ranges: [["00:00:00", "23:30:00", 1800]]
    initial: "00:00:00"
    format: "hh:mm"
    wrap: true
actions:
  press_warm: {control: warm_button}
  press_off: {control: off_button}
  press_up: {control: up_button}
features:
  hold_hours:
    - {actions: [press_warm], variable: hold_hours, effect: none}
    - {actions: [press_up], variable: hold_hours, effect: next}
  auto_off:
    - {actions: [press_off], variable: auto_off, effect: none}
    - {actions: [press_up], variable: auto_off, effect: next}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def warmer() -> ApplianceModel:
    return loads_model(WARMER)


def test_hours_held_from_empty_take_a_duration(warmer: ApplianceModel) -> None:
    assert parse_instruction(warmer, "hold the food for 4 hours") == {"hold_hours": "04:00:00"}


def test_a_timer_from_empty_takes_a_hyphenated_duration(warmer: ApplianceModel) -> None:
    goal = parse_instruction(warmer, "set a 3-hour auto off")
    assert goal == {"auto_off": "03:00:00"}
