"""A number setting named a time but without a unit takes a duration said without naming it,
as the number said (goal_unitless). A model written for this test: a foot massager whose
SESSION TIME 1-15 has no unit."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

MASSAGER = """
appliance: {id: massager_9, category: foot_massager, name: "Kneda FM-9 foot massager", brand: K}
controls:
  - {id: time_button, kind: button, label: "TIME"}
  - {id: level_button, kind: button, label: "LEVEL"}
variables:
  session_time:
    type: numeric
    ranges: [[1, 15, 1]]
    initial: 10
    wrap: true
    show: "{value}:00"
  level:
    type: numeric
    ranges: [[1, 30, 1]]
    initial: 5
    wrap: true
    label: "LEVEL"
actions:
  press_time: {control: time_button}
  press_level: {control: level_button}
features:
  session_time:
    - {actions: [press_time], variable: session_time, effect: next}
  level:
    - {actions: [press_level], variable: level, effect: next}
display:
  idle: "{level}"
"""


def test_a_duration_goes_to_the_setting_named_a_time() -> None:
    goal = parse_instruction(loads_model(MASSAGER), "Twelve minutes at level 20")
    assert goal == {"session_time": 12, "level": 20}


def test_a_duration_outside_its_values_is_not_taken() -> None:
    goal = parse_instruction(loads_model(MASSAGER), "Level 20 for 40 minutes")
    assert "session_time" not in goal
