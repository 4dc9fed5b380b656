"""The mode a setting's value implies (goal_cases), checked on models written for these tests:
a grow box whose presets fix the light time that only CUSTOM lets the user choose, a fan level
and a watering dose that other cases lack; an oven whose keys enter a mode before a setting."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

GROW_BOX = """
appliance: {id: grow_1, category: grow_box, name: "Sprout GB-3 grow box", brand: S}
controls:
  - {id: prog_button, kind: button, label: "PROG"}
  - {id: what_button, kind: button, label: "SELECT"}
  - {id: plus_button, kind: button, label: "+"}
  - {id: minus_button, kind: button, label: "-"}
  - {id: fan_button, kind: button, label: "FAN"}
  - {id: dose_button, kind: button, label: "DOSE"}
variables:
  preset:
    type: discrete
    values: [seedling, bloom, custom]
  light_hours:
    type: numeric
    unit: h
    depends_on: preset
    cases:
      seedling: {ranges: [[16, 16, 1]], initial: 16}
      bloom: {ranges: [[12, 12, 1]], initial: 12}
      custom: {ranges: [[6, 20, 1]], initial: 14}
    label: "LIGHT"
  fan_level:
    type: numeric
    depends_on: preset
    cases:
      custom: {ranges: [[1, 5, 1]], initial: 3}
    label: "FAN"
  target:
    type: discrete
    values: [humidity, water]
  humidity:
    type: numeric
    unit: "%"
    depends_on: target
    cases:
      humidity: {ranges: [[40, 80, 5]], initial: 60}
  water:
    type: numeric
    unit: ml
    depends_on: target
    cases:
      water: {ranges: [[50, 500, 50]], initial: 100}
actions:
  press_prog: {control: prog_button}
  press_what: {control: what_button}
  press_plus: {control: plus_button}
  press_minus: {control: minus_button}
  press_fan: {control: fan_button}
  press_dose: {control: dose_button}
features:
  preset:
    - {actions: [press_prog], variable: preset, effect: next}
    - actions: [press_plus, press_minus]
      variable: light_hours
      effect: {press_plus: next, press_minus: prev}
  fan:
    - {actions: [press_fan]}
    - actions: [press_plus, press_minus]
      variable: fan_level
      effect: {press_plus: next, press_minus: prev}
  target:
    - {actions: [press_what], variable: target, effect: next}
    - actions: [press_plus, press_minus]
      variable: humidity
      effect: {press_plus: next, press_minus: prev}
  water:
    - {actions: [press_dose]}
    - actions: [press_plus, press_minus]
      variable: water
      effect: {press_plus: next, press_minus: prev}
display:
  idle: "{preset}"
"""


def _model(starts: str = "seedling") -> ApplianceModel:
    return loads_model(
        GROW_BOX.replace(
            "values: [seedling, bloom, custom]",
            f"values: [seedling, bloom, custom]\n    initial: {starts}",
        )
    )


def test_a_value_only_the_one_free_case_admits_sets_that_case() -> None:
    goal = parse_instruction(_model(), "Give the plants 18 hours of light")
    assert goal == {"light_hours": 18, "preset": "custom"}


def test_a_value_two_cases_could_hold_leaves_the_mode_alone() -> None:
    assert parse_instruction(_model(), "12 hours of light a day") == {"light_hours": 12}


def test_a_case_the_panel_starts_in_is_not_added() -> None:
    goal = parse_instruction(_model("custom"), "Give the plants 18 hours of light")
    assert goal == {"light_hours": 18}


def test_a_setting_the_other_cases_lack_leaves_the_mode_alone() -> None:
    assert parse_instruction(_model(), "Put the fan on level 4") == {"fan_level": 4}
    assert parse_instruction(_model(), "Pour in 200 ml each morning") == {"water": 200}


OVEN = """
appliance: {id: oven_8, category: combi_oven, name: "Tessa CO-8 combination oven", brand: T}
controls:
  - {id: micro_button, kind: button, label: "MICRO"}
  - {id: fan_button, kind: button, label: "FAN OVEN"}
  - {id: thaw_button, kind: button, label: "THAW"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
variables:
  mode:
    type: discrete
    values: [micro, fan, thaw]
  watts:
    type: numeric
    unit: W
    ranges: [[100, 800, 100]]
    initial: 800
  fan_temp:
    type: numeric
    unit: "°C"
    ranges: [[100, 220, 10]]
    initial: 160
  thaw_weight:
    type: numeric
    unit: g
    ranges: [[100, 1500, 100]]
    initial: 500
actions:
  press_micro: {control: micro_button}
  press_fan: {control: fan_button}
  press_thaw: {control: thaw_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  micro:
    - {actions: [press_micro], variable: mode, effect: {to: micro}}
    - actions: [press_up, press_down]
      variable: watts
      effect: {press_up: next, press_down: prev}
  fan_oven:
    - {actions: [press_fan], variable: mode, effect: {to: fan}}
    - actions: [press_up, press_down]
      variable: fan_temp
      effect: {press_up: next, press_down: prev}
  thaw:
    - {actions: [press_thaw], variable: mode, effect: {to: thaw}}
    - actions: [press_up, press_down]
      variable: thaw_weight
      effect: {press_up: next, press_down: prev}
display:
  idle: "{mode}"
"""


def test_a_setting_entered_through_one_mode_sets_that_mode() -> None:
    oven = loads_model(OVEN)
    assert parse_instruction(oven, "Heat the rolls at 180 degrees") == {
        "fan_temp": 180,
        "mode": "fan",
    }
    assert parse_instruction(oven, "600 g of mince, by weight") == {
        "thaw_weight": 600,
        "mode": "thaw",
    }


def test_the_mode_the_oven_starts_in_is_not_added() -> None:
    assert parse_instruction(loads_model(OVEN), "Warm it at 500 W") == {"watts": 500}


HOB = """
appliance: {id: hob_8, category: hot_plate, name: "Plato HP-8 hot plate", brand: P}
controls:
  - {id: level_button, kind: button, label: "LEVEL"}
  - {id: temp_button, kind: button, label: "TEMP"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
variables:
  select:
    type: discrete
    values: [level, temp]
  level:
    type: numeric
    depends_on: select
    cases:
      level: {ranges: [[1, 9, 1]], initial: 5}
  temp:
    type: numeric
    unit: "°C"
    depends_on: select
    cases:
      temp: {ranges: [[60, 240, 20]], initial: 160}
actions:
  press_level: {control: level_button}
  press_temp: {control: temp_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  level:
    - {actions: [press_level], variable: select, effect: {to: level}}
    - actions: [press_up, press_down]
      variable: level
      effect: {press_up: next, press_down: prev}
  temp:
    - {actions: [press_temp], variable: select, effect: {to: temp}}
    - actions: [press_up, press_down]
      variable: temp
      effect: {press_up: next, press_down: prev}
display:
  idle: "{select}"
"""


def test_a_selector_key_before_a_setting_other_cases_lack_is_not_added() -> None:
    assert parse_instruction(loads_model(HOB), "Fry it at 180 degrees") == {"temp": 180}
