"""An ordinal before a setting's noun is its number: "the second tray" is tray 2 (a value T2),
"the third day" day 3 (a day count); "a 30 second soak" keeps its seconds. Checked on a
seed-sprouter panel written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

SPROUTER = """
appliance: {id: sprouter_1, category: sprouter, name: "Vera S3 seed sprouter", brand: V}
controls:
  - {id: tray_button, kind: button, label: "TRAY"}
  - {id: day_button, kind: button, label: "DAY"}
  - {id: soak_button, kind: button, label: "SOAK"}
variables:
  tray:
    type: discrete
    values: [T1, T2, T3]
  day:
    type: numeric
    ranges: [[1, 9, 1]]
  soak:
    type: numeric
    unit: s
    ranges: [[10, 60, 10]]
actions:
  press_tray: {control: tray_button}
  press_day: {control: day_button}
  press_soak: {control: soak_button}
features:
  tray:
    - {actions: [press_tray], variable: tray, effect: next}
  day:
    - {actions: [press_day], variable: day, effect: next}
  soak:
    - {actions: [press_soak], variable: soak, effect: next}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def sprouter() -> ApplianceModel:
    return loads_model(SPROUTER)


def test_an_ordinal_before_a_numbered_setting_is_its_number(sprouter: ApplianceModel) -> None:
    assert parse_instruction(sprouter, "Select the second tray.") == {"tray": "T2"}
    assert parse_instruction(sprouter, "We are on the third day.") == {"day": 3}


def test_seconds_after_a_number_stay_seconds(sprouter: ApplianceModel) -> None:
    assert parse_instruction(sprouter, "A 30 second soak on tray 1.") == {"soak": 30, "tray": "T1"}


def test_an_ordinal_that_orders_the_steps_is_no_number(sprouter: ApplianceModel) -> None:
    """ "First tray 2, …" says the number itself: the ordinal only orders the steps."""
    assert parse_instruction(sprouter, "First tray 2, second a 20 second soak.") == {
        "tray": "T2",
        "soak": 20,
    }


_PROGRAM_FEATURE = "  program:\n    - {actions: [press_program], variable: program, effect: next}\n"
PROGRAMMED = (
    SPROUTER.replace(
        "variables:\n", "variables:\n  program:\n    type: discrete\n    values: [P1, P2, P3]\n"
    )
    .replace("features:\n", "features:\n" + _PROGRAM_FEATURE)
    .replace("actions:\n", "actions:\n  press_program: {control: program_button}\n")
    .replace("controls:\n", 'controls:\n  - {id: program_button, kind: button, label: "PROGRAM"}\n')
)


def test_an_ordinal_before_a_verb_and_its_object_is_no_number() -> None:
    """ "First program the soak …": "program" is the verb, the ordinal the step's order."""
    model = loads_model(PROGRAMMED)
    assert parse_instruction(model, "First program the soak for 20 seconds.") == {"soak": 20}
    assert parse_instruction(model, "Run the second program.") == {"program": "P2"}
