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


ROASTER = """
appliance: {id: roaster_1, category: bench_oven, name: "Hotbox H3 bench oven", brand: H}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: temp_button, kind: button, label: "TEMP"}
variables:
  mode:
    type: discrete
    values: [roast, fan_roast, toast]
  temperature:
    type: numeric
    unit: C
    ranges: [[100, 240, 20]]
    wrap: true
    initial: 180
actions:
  press_mode: {control: mode_button}
  press_temp: {control: temp_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  temperature:
    - {actions: [press_temp], variable: temperature, effect: next}
display:
  idle: ""
"""


@pytest.mark.parametrize(
    "text",
    ["Roast the chicken in my fan oven at 200", "Roast at 200 in the fan bench oven"],
)
def test_a_word_before_the_appliance_itself_names_no_value(text: str) -> None:
    """ "the fan oven" is what kind of oven it is, not the FAN ROAST programme: the oven is the
    appliance, not something it works on."""
    assert parse_instruction(loads_model(ROASTER), text).get("mode") == "roast"
