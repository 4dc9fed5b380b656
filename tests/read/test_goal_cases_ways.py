"""A mode with a setting in only one of its three or more cases is a way of working: saying
that setting asks for the case (goal_cases). A two-way AUTO / MAN mode is left alone. Models
written for these tests: a patio heater with a countdown only in its TIMED way of working, and
a pump whose hours exist only in MAN."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

HEATER = """
appliance: {id: heater_9, category: patio_heater, name: "Glow PH-9 patio heater", brand: G}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: hours_button, kind: button, label: "HOURS"}
  - {id: level_button, kind: button, label: "LEVEL"}
variables:
  mode:
    type: discrete
    values: [continuous, thermostat, timed]
  hours:
    type: numeric
    unit: h
    depends_on: mode
    wrap: true
    label: "HOURS"
    cases:
      timed: {ranges: [[1, 6, 1]], initial: 2}
  level:
    type: numeric
    ranges: [[1, 3, 1]]
    initial: 2
    wrap: true
    label: "LEVEL"
actions:
  press_mode: {control: mode_button}
  press_hours: {control: hours_button}
  press_level: {control: level_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  hours:
    - {actions: [press_hours], variable: hours, effect: next}
  level:
    - {actions: [press_level], variable: level, effect: next}
display:
  idle: "{mode}"
"""


def test_a_setting_of_the_only_case_that_has_one_sets_that_case() -> None:
    goal = parse_instruction(loads_model(HEATER), "Heat the terrace for 3 hours at level 2")
    assert goal["hours"] == 3 and goal["mode"] == "timed"


def test_a_two_way_auto_or_manual_mode_is_left_alone() -> None:
    two_way = loads_model(
        HEATER.replace("[continuous, thermostat, timed]", "[auto, timed]")
        .replace("category: patio_heater", "category: pool_pump")
        .replace("patio heater", "pool pump")
    )
    goal = parse_instruction(two_way, "Run for 3 hours at level 2")
    assert goal["hours"] == 3 and "mode" not in goal


TAP = """
appliance: {id: tap_9, category: water_tap, name: "Fonta WT-9 water tap", brand: F}
controls:
  - {id: water_button, kind: button, label: "WATER"}
  - {id: temp_button, kind: button, label: "TEMP"}
variables:
  water:
    type: discrete
    values: [room, cold, hot]
  temperature:
    type: numeric
    unit: "°C"
    depends_on: water
    wrap: true
    label: "TEMP"
    cases:
      hot: {ranges: [[50, 90, 10]], initial: 70}
      cold: {ranges: [[4, 10, 3]], initial: 7}
actions:
  press_water: {control: water_button}
  press_temp: {control: temp_button}
features:
  water:
    - {actions: [press_water], variable: water, effect: next}
  temperature:
    - {actions: [press_temp], variable: temperature, effect: next}
display:
  idle: "{water}"
"""


def test_a_value_only_one_case_has_tells_the_case() -> None:
    goal = parse_instruction(loads_model(TAP), "A glass at 60 °C")
    assert goal == {"temperature": 60, "water": "hot"}
