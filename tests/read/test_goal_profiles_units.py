"""A person's profile and a selector of units said in words: "a 27-year-old woman" gives an
AGE and a SEX; "readings in Fahrenheit", "in stones" name a unit selector's value; "Switch
the …" is no unit's initials. Small models written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SCALE = """
appliance: {id: scale_9, category: bathroom_scale, name: "Poise P-9 scale", brand: P}
controls:
  - {id: set_key, kind: button, label: "SET"}
  - {id: unit_key, kind: button, label: "UNIT"}
  - {id: age_key, kind: button, label: "AGE"}
variables:
  unit:
    type: discrete
    values: [kg, lb, st]
  sex:
    type: discrete
    values: [male, female]
  age:
    type: numeric
    ranges: [[10, 99, 1]]
    wrap: true
actions:
  press_set: {control: set_key}
  press_unit: {control: unit_key}
  press_age: {control: age_key}
features:
  unit:
    - {actions: [press_unit], variable: unit, effect: next}
  sex:
    - {actions: [press_set], variable: sex, effect: next}
  age:
    - {actions: [press_age], variable: age, effect: next}
"""


def test_an_age_said_as_years_old() -> None:
    model = loads_model(SCALE)
    assert parse_instruction(model, "a 41-year-old woman") == {"age": 41, "sex": "female"}
    assert parse_instruction(model, "he is a man, thirty-four years old") == {
        "age": 34,
        "sex": "male",
    }


def test_a_unit_named_in_words_with_no_number() -> None:
    model = loads_model(SCALE)
    assert parse_instruction(model, "I weigh myself in stones") == {"unit": "st"}
    assert parse_instruction(model, "Switch the scale to pounds") == {"unit": "lb"}


PROBE = """
appliance: {id: probe_9, category: meat_thermometer, name: "Probe T-9", brand: P}
controls:
  - {id: unit_switch, kind: switch, label: "°C/°F"}
  - {id: alarm_key, kind: button, label: "ALARM"}
variables:
  unit:
    type: discrete
    values: [c, f]
    show: {c: "°C", f: "°F"}
  alarm:
    type: discrete
    values: ["on", "off"]
actions:
  slide_unit: {control: unit_switch}
  press_alarm: {control: alarm_key}
features:
  unit:
    - {actions: [slide_unit], variable: unit, effect: toggle}
  alarm:
    - {actions: [press_alarm], variable: alarm, effect: toggle}
"""


def test_a_temperature_scale_named_alone() -> None:
    model = loads_model(PROBE)
    assert parse_instruction(model, "show the readings in Fahrenheit") == {"unit": "f"}
