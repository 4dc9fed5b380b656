"""A clause that opens with a setting's own name and a bare number ("heat 7,") names the
setting and its value; it does not start the appliance as an opening verb would (goal_start).
A model written for this test: a hot plate with HEAT 1-9, TIME and START."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

PLATE = """
appliance: {id: plate_9, category: hot_plate, name: "Calor HP-9 hot plate", brand: C}
controls:
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: time_button, kind: button, label: "TIME"}
  - {id: start_button, kind: button, label: "START"}
variables:
  heat:
    type: numeric
    ranges: [[1, 9, 1]]
    initial: 5
    wrap: true
    label: "HEAT"
  cook_time:
    type: numeric
    unit: min
    ranges: [[1, 30, 1]]
    initial: 10
    wrap: true
    label: "TIME"
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_heat: {control: heat_button}
  press_time: {control: time_button}
  press_start: {control: start_button}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
  cook_time:
    - {actions: [press_time], variable: cook_time, effect: next}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
display:
  idle: "{heat}"
"""


def test_a_setting_named_with_a_bare_number_does_not_start() -> None:
    goal = parse_instruction(loads_model(PLATE), "Thin pancakes, heat 7, four minutes.")
    assert goal == {"heat": 7, "cook_time": 4}


def test_a_doing_verb_still_starts() -> None:
    goal = parse_instruction(loads_model(PLATE), "Heat the soup at level 7 for four minutes.")
    assert goal.get("running") == "on"
