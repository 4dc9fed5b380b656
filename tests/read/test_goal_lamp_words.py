"""A switch is named by the one word its display lamp lights while it is on (PUMP for the
recirculation a RECIRC key switches): said as a noun, as lit — "nearly boiling" is no BOIL
lamp — and never a general word (AUTO) or another setting's word. A small brewer-like model
written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

BREWER = """
appliance: {id: brewer_1, category: brewer, name: "Malt B-1 brewer", brand: M}
controls:
  - {id: recirc_key, kind: button, label: "RECIRC"}
  - {id: again_key, kind: button, label: "AGAIN"}
  - {id: sensor_key, kind: button, label: "SENSOR"}
  - {id: temp_key, kind: button, label: "TEMP"}
variables:
  recirculation: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "PUMP"}}
  reheat: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "BOIL"}}
  sensor: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "AUTO"}}
  temperature: {type: numeric, unit: "°C", ranges: [[60, 100, 1]]}
actions:
  press_recirc: {control: recirc_key}
  press_again: {control: again_key}
  press_sensor: {control: sensor_key}
  press_temp: {control: temp_key}
features:
  recirculation:
    - {actions: [press_recirc], variable: recirculation, effect: toggle}
  reheat:
    - {actions: [press_again], variable: reheat, effect: toggle}
  sensor:
    - {actions: [press_sensor], variable: sensor, effect: toggle}
  temperature:
    - {actions: [press_temp], variable: temperature, effect: next}
"""


def _goal(text: str) -> dict[str, object]:
    return parse_instruction(loads_model(BREWER), text)


def test_the_word_a_lamp_lights_names_its_switch() -> None:
    assert _goal("68 degrees with the pump on") == {"temperature": 68, "recirculation": "on"}
    assert _goal("bring it back to the boil")["reheat"] == "on"


def test_a_lamp_word_said_otherwise_or_general_names_nothing() -> None:
    assert _goal("keep it nearly boiling, at 98 degrees") == {"temperature": 98}
    assert "sensor" not in _goal("75 degrees, automatic")
