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


WARMER = """
appliance: {id: kettle_9, category: kettle, name: "Boilo K9 kettle", brand: B}
controls:
  - {id: warm_button, kind: button, label: "KEEP WARM"}
  - {id: temp_button, kind: button, label: "TEMP"}
variables:
  keep_warm: {type: discrete, values: ["off", "on"]}
  temperature: {type: numeric, ranges: [[40, 100, 10]], unit: "°C", initial: 100, wrap: true}
actions:
  press_warm: {control: warm_button}
  press_temp: {control: temp_button}
features:
  warm:
    - {actions: [press_warm], variable: keep_warm, effect: toggle}
  temp:
    - {actions: [press_temp], variable: temperature, effect: next}
display:
  idle: ""
"""


@pytest.mark.parametrize(
    ("instruction", "expected"),
    [
        ("Water at 80 °C, a bit warmer than usual.", {"temperature": 80}),
        ("Make it warmer today: 90 degrees.", {"temperature": 90}),
        ("Keep it warm at 80.", {"temperature": 80, "keep_warm": "on"}),
    ],
)
def test_a_comparative_is_no_doer(instruction: str, expected: dict[str, object]) -> None:
    """ "warmer" is WARM's "-er" form, but said as a comparative it names no KEEP WARM."""
    assert dict(parse_instruction(loads_model(WARMER), instruction)) == expected
