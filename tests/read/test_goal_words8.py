"""How people name moving air: circulation and ventilation are the fan (a FAN mode, an AIR
switch), checked on a cheese-ripening cabinet written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

CABINET = """
appliance: {id: cave_1, category: cheese_cabinet, name: "Affine CC-2 ripening cabinet", brand: A}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: air_button, kind: button, label: "AIR"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
variables:
  mode:
    type: discrete
    values: [chill, fan, mist]
  air:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "AIR"}
  temperature:
    type: numeric
    unit: "°C"
    ranges: [[6, 16, 1]]
    initial: 12
actions:
  press_mode: {control: mode_button}
  press_air: {control: air_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  air:
    - {actions: [press_air], variable: air, effect: toggle}
  temperature:
    - actions: [press_up, press_down]
      variable: temperature
      effect: {press_up: next, press_down: prev}
display:
  idle: "{temperature}"
"""


def _model(modes: str = "chill, dry, mist") -> ApplianceModel:
    return loads_model(CABINET.replace("chill, fan, mist", modes))


def test_ventilation_names_the_air_switch() -> None:
    goal = parse_instruction(_model(), "10 degrees, and switch the ventilation on")
    assert goal == {"temperature": 10, "air": "on"}


def test_circulation_names_the_air_switch() -> None:
    goal = parse_instruction(_model(), "Keep the air circulation off and hold it at 8 °C")
    assert goal == {"air": "off", "temperature": 8}


def test_circulating_names_the_fan_mode() -> None:
    goal = parse_instruction(_model("chill, fan, mist"), "Only circulate, no chilling")
    assert goal == {"mode": "fan"}
