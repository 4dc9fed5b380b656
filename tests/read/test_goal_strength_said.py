"""A strength said without the setting's name ("the softest level", "as strong as it goes",
"the paddles on the gentlest level") is said of the one plain numbered level of the model (no
unit, not a time); a word of strength compared ("as strong as") is no synonym of HIGH heat; and
"put X on the … level" sets a level, it is no remark about where to put something. Checked on a
seat massager and a paddle foot bath written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

MASSAGER = """
appliance: {id: seat_1, category: seat_massager, name: "Knotless SM-5 seat massager", brand: K}
controls:
  - {id: level_button, kind: button, label: "INTENSITY"}
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: style_button, kind: button, label: "STYLE"}
  - {id: softer_button, kind: button, label: "-"}
variables:
  intensity:
    type: numeric
    ranges: [[1, 5, 1]]
    initial: 3
  heat:
    type: discrete
    values: ["off", low, high]
  style:
    type: discrete
    values: [knead, roll, tap]
actions:
  press_level: {control: level_button}
  press_heat: {control: heat_button}
  press_style: {control: style_button}
  press_softer: {control: softer_button}
features:
  intensity:
    - {actions: [press_level], variable: intensity, effect: next}
    - {actions: [press_softer], variable: intensity, effect: prev}
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
  style:
    - {actions: [press_style], variable: style, effect: next}
display:
  idle: ""
"""

BATH = """
appliance: {id: bath_1, category: foot_bath, name: "Tidewell FB-2 foot bath", brand: T}
controls:
  - {id: paddle_button, kind: button, label: "MASSAGE"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
variables:
  massage:
    type: discrete
    values: ["off", "1", "2", "3"]
  temperature:
    type: numeric
    unit: "°C"
    ranges: [[30, 45, 1]]
    initial: 38
actions:
  press_paddle: {control: paddle_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  massage:
    - {actions: [press_paddle], variable: massage, effect: next}
  temperature:
    - {actions: [press_up], variable: temperature, effect: next}
    - {actions: [press_down], variable: temperature, effect: prev}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def massager() -> ApplianceModel:
    return loads_model(MASSAGER)


@pytest.fixture(scope="module")
def bath() -> ApplianceModel:
    return loads_model(BATH)


@pytest.mark.parametrize(
    ("text", "level"),
    [
        ("Rolling, at the softest level, heat on high.", 1),
        ("Kneading, as strong as it goes, please.", 5),
        ("Tap at the weakest level with the heat off", 1),
    ],
)
def test_a_strength_is_said_of_the_plain_level(
    massager: ApplianceModel, text: str, level: int
) -> None:
    assert parse_instruction(massager, text, "", []).get("intensity") == level


def test_as_strong_as_is_no_high_heat(massager: ApplianceModel) -> None:
    assert "heat" not in parse_instruction(massager, "Kneading, as strong as it goes.", "", [])
    assert parse_instruction(massager, "Kneading with a gentle heat.", "", [])["heat"] == "low"


@pytest.mark.parametrize(
    ("text", "paddle"),
    [
        ("The paddles on the gentlest level.", "1"),
        ("Warm it to 40 °C, then put the paddles on the strongest level.", "3"),
    ],
)
def test_putting_a_thing_on_a_level_sets_it(bath: ApplianceModel, text: str, paddle: str) -> None:
    assert parse_instruction(bath, text, "", []).get("massage") == paddle
