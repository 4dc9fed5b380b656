"""A setting's name word and the name of what does it are swapped freely: a HEAT setting is
"the heater", a DIMMER switch is "dim it". Checked on a desk lamp-heater written for these
tests; a word of the appliance's own name and a word in "-e" (TIME, not TIMER) make no doer."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction
from apbot.read.goal_vocab import doer_forms

LAMP = """
appliance: {id: lamp_1, category: desk_lamp, name: "Glow D2 desk lamp", brand: G}
controls:
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: dimmer_button, kind: button, label: "DIMMER"}
  - {id: fan_button, kind: button, label: "FAN"}
variables:
  heat:
    type: discrete
    values: ["off", "eco", "full"]
  dimmer:
    type: discrete
    values: ["off", "on"]
  fan:
    type: discrete
    values: ["off", "on"]
actions:
  press_heat: {control: heat_button}
  press_dimmer: {control: dimmer_button}
  press_fan: {control: fan_button}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
  dimmer:
    - {actions: [press_dimmer], variable: dimmer, effect: toggle}
  fan:
    - {actions: [press_fan], variable: fan, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def lamp() -> ApplianceModel:
    return loads_model(LAMP)


@pytest.mark.parametrize(
    ("instruction", "expected"),
    [
        ("Turn the heater off and the fan on.", {"heat": "off", "fan": "on"}),
        ("Fan on, light dimmed.", {"fan": "on", "dimmer": "on"}),
    ],
)
def test_doer_names_the_setting(
    lamp: ApplianceModel, instruction: str, expected: dict[str, str]
) -> None:
    assert dict(parse_instruction(lamp, instruction)) == expected


def test_doer_forms() -> None:
    assert doer_forms("heat") == ["heater"]
    assert doer_forms("dimmer") == ["dim"]
    assert doer_forms("buzzer") == ["buzz"]
    assert doer_forms("timer") == doer_forms("time") == doer_forms("freeze") == []
