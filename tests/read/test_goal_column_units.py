"""Pressure units said as a column of liquid ("inches of mercury", "centimetres of water") or by
their plain words ("in hectopascals", "pressure in inches"), on a model written for these tests
(a barometer clock no suite has): each names the one unit of the selector that offers it."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

BAROMETER = """
appliance: {id: baro_1, category: barometer_clock, name: "Deck barometer clock", brand: B}
controls:
  - {id: unit_key, kind: button, label: "UNIT"}
  - {id: scale_key, kind: button, label: "C/F"}
variables:
  air_unit: {type: discrete, values: [hpa, inhg, mmhg], show: {hpa: hPa, inhg: inHg, mmhg: mmHg}}
  scale: {type: discrete, values: [c, f], show: {c: "°C", f: "°F"}}
actions:
  press_unit: {control: unit_key}
  press_scale: {control: scale_key}
features:
  air_unit:
    - {actions: [press_unit], variable: air_unit, effect: next}
  scale:
    - {actions: [press_scale], variable: scale, effect: next}
"""


@pytest.mark.parametrize(
    ("sentence", "unit"),
    [
        ("Readings in Fahrenheit, and the air pressure in inches of mercury.", "inhg"),
        ("Air pressure in millimetres of mercury please, and Fahrenheit.", "mmhg"),
        ("Fahrenheit, with the pressure in inches.", "inhg"),
        ("Show Fahrenheit and put the pressure in hectopascals.", "hpa"),
    ],
)
def test_a_pressure_unit_said_in_words(sentence: str, unit: str) -> None:
    goal = dict(parse_instruction(loads_model(BAROMETER), sentence))
    assert goal == {"scale": "f", "air_unit": unit}
