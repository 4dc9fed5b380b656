"""A value named by its distinctive word before what the appliance works on ("an AGM battery"
on a battery charger): the word says which kind of that thing, so it names the value whose
other words it shares with its siblings. Checked on a tyre inflator written for these tests
(AUTO ROAD / AUTO MOUNTAIN / MANUAL, pressure in bar)."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

INFLATOR = """
appliance: {id: inflator_1, category: tyre_inflator, name: "Puff P9 tyre inflator", brand: P}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: minus_button, kind: button, label: "-"}
  - {id: plus_button, kind: button, label: "+"}
variables:
  mode:
    type: discrete
    values: [auto road, auto mountain, auto city, manual]
  pressure:
    type: numeric
    unit: bar
    ranges: [[1, 8, 0.5]]
    initial: 2
actions:
  press_mode: {control: mode_button}
  press_minus: {control: minus_button}
  press_plus: {control: plus_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  pressure:
    - actions: [press_minus, press_plus]
      variable: pressure
      effect: {press_minus: prev, press_plus: next}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def inflator() -> ApplianceModel:
    return loads_model(INFLATOR)


@pytest.mark.parametrize(
    ("text", "mode"),
    [
        ("Pump my mountain tyre up to 2.5 bar", "auto mountain"),
        ("It's a road tyre, 7 bar please", "auto road"),
        ("Fill the front city auto tyre to 3 bar", "auto city"),
    ],
)
def test_a_distinctive_word_before_the_appliances_own_thing_names_the_value(
    inflator: ApplianceModel, text: str, mode: str
) -> None:
    assert parse_instruction(inflator, text).get("mode") == mode


def test_the_word_elsewhere_names_no_value(inflator: ApplianceModel) -> None:
    goal = parse_instruction(inflator, "3 bar, we ride in the mountain on Sunday")
    assert goal == {"pressure": 3}
