"""A setting kept in the unit a selector chooses: "110 °F" sets the scale to Fahrenheit and
the temperature in its case; "22 °dH" on a panel that starts in °dH sets the hardness alone;
"grains per gallon" names GPG by its initials. Checked on a bath and a softener written for
these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

BATH = """
appliance: {id: bath_1, category: foot_bath, name: "Soakit FB-2 foot bath", brand: S}
controls:
  - {id: scale_button, kind: button, label: "°C/°F"}
  - {id: up_button, kind: button, label: "+"}
variables:
  scale:
    type: discrete
    values: [celsius, fahrenheit]
    show: {celsius: "°C", fahrenheit: "°F"}
  temperature:
    type: numeric
    depends_on: scale
    wrap: true
    cases:
      celsius: {ranges: [[30, 45, 1]], initial: 38}
      fahrenheit: {ranges: [[86, 113, 1]], initial: 100}
actions:
  press_scale: {control: scale_button}
  press_up: {control: up_button}
features:
  scale:
    - {actions: [press_scale], variable: scale, effect: toggle}
  temperature:
    - {actions: [press_up], variable: temperature, effect: next}
display:
  idle: "{temperature}"
"""

SOFTENER = """
appliance: {id: soft_1, category: softener, name: "Aqualis S-3 softener", brand: A}
controls:
  - {id: unit_button, kind: button, label: "UNIT"}
  - {id: up_button, kind: button, label: "+"}
variables:
  unit:
    type: discrete
    values: [dh, ppm, gpg]
    show: {dh: "°dH", ppm: "ppm", gpg: "gpg"}
  hardness:
    type: numeric
    depends_on: unit
    wrap: true
    cases:
      dh: {ranges: [[1, 40, 1]], initial: 15}
      ppm: {ranges: [[20, 700, 10]], initial: 270}
      gpg: {ranges: [[1, 40, 1]], initial: 16}
actions:
  press_unit: {control: unit_button}
  press_up: {control: up_button}
features:
  unit:
    - {actions: [press_unit], variable: unit, effect: next}
  hardness:
    - {actions: [press_up], variable: hardness, effect: next}
display:
  idle: "{hardness}"
"""


def test_a_number_in_a_unit_the_selector_offers() -> None:
    bath = loads_model(BATH)
    assert parse_instruction(bath, "Heat it to 104 °F, please") == {
        "scale": "fahrenheit",
        "temperature": 104,
    }
    assert parse_instruction(bath, "Water at 95 degrees Fahrenheit") == {
        "scale": "fahrenheit",
        "temperature": 95,
    }


def test_the_starting_unit_and_a_unit_in_initials() -> None:
    softener = loads_model(SOFTENER)
    assert parse_instruction(softener, "Our water tests at 22 °dH, enter that") == {"hardness": 22}
    assert parse_instruction(softener, "Hardness is 18 grains per gallon") == {
        "unit": "gpg",
        "hardness": 18,
    }
    assert parse_instruction(softener, "Switch to parts per million")["unit"] == "ppm"


def test_a_scale_read_as_its_letter_is_said_by_its_name() -> None:
    """A reader names the scales by their signs (°c, °f): "degrees Fahrenheit" still says °f."""
    text = BATH.replace("[celsius, fahrenheit]", '["°c", "°f"]')
    text = text.replace('{celsius: "°C", fahrenheit: "°F"}', '{"°c": "°C", "°f": "°F"}')
    text = text.replace("celsius: {ranges", '"°c": {ranges').replace(
        "fahrenheit: {ranges", '"°f": {ranges'
    )
    bath = loads_model(text)
    assert parse_instruction(bath, "Water at 95 degrees Fahrenheit") == {
        "scale": "°f",
        "temperature": 95,
    }
