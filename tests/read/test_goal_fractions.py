"""Parts of a measure said in words ("half a cup", "three eighths of a scoop") set the setting
whose values are those parts, written as fractions or named HALF / QUARTER; a part of an hour
or a mixed number stays a quantity. Checked on two models written for these tests: a grain
dispenser with portions 1/8 … 1 and a drinks maker with QUARTER / HALF / THREE QUARTERS."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

DISPENSER = """
appliance: {id: grain_1, category: grain_dispenser, name: "Granny G4 grain dispenser", brand: G}
controls:
  - {id: slot_button, kind: button, label: "SLOT"}
  - {id: amount_button, kind: button, label: "AMOUNT"}
  - {id: rinse_button, kind: button, label: "RINSE"}
variables:
  slot:
    type: discrete
    values: [S1, S2]
  amount:
    type: discrete
    values: ["1/8", "1/4", "3/8", "1/2", "5/8", "3/4", "7/8", "1"]
    initial: "1/4"
  rinse:
    type: discrete
    values: ["off", "on"]
actions:
  press_slot: {control: slot_button}
  press_amount: {control: amount_button}
  press_rinse: {control: rinse_button}
features:
  slot:
    - {actions: [press_slot], variable: slot, effect: next}
  amount:
    - {actions: [press_amount], variable: amount, effect: next}
  rinse:
    - {actions: [press_rinse], variable: rinse, effect: toggle}
display:
  idle: ""
"""

DRINKS = """
appliance: {id: drinks_1, category: drinks_maker, name: "Frothy F1 drinks maker", brand: F}
controls:
  - {id: drink_button, kind: button, label: "DRINK"}
  - {id: fill_button, kind: button, label: "FILL"}
  - {id: time_minus, kind: button, label: "-"}
  - {id: time_plus, kind: button, label: "+"}
variables:
  drink:
    type: discrete
    values: [cocoa, latte, tea]
  fill:
    type: discrete
    values: [quarter, half, three_quarters]
    show: {quarter: "1/4", half: "1/2", three_quarters: "3/4"}
  hold_time:
    type: numeric
    unit: min
    ranges: [[0, 60, 5]]
    initial: 0
actions:
  press_drink: {control: drink_button}
  press_fill: {control: fill_button}
  press_minus: {control: time_minus}
  press_plus: {control: time_plus}
features:
  drink:
    - {actions: [press_drink], variable: drink, effect: next}
  fill:
    - {actions: [press_fill], variable: fill, effect: next}
  hold_time:
    - actions: [press_minus, press_plus]
      variable: hold_time
      effect: {press_minus: prev, press_plus: next}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def dispenser() -> ApplianceModel:
    return loads_model(DISPENSER)


@pytest.fixture(scope="module")
def drinks() -> ApplianceModel:
    return loads_model(DRINKS)


@pytest.mark.parametrize(
    ("text", "amount"),
    [
        ("Put out half a cup of rice from S2", "1/2"),
        ("three eighths of a cup, please", "3/8"),
        ("Rinse it and give one eighth of a cup", "1/8"),
        ("a quarter cup from slot S1", "1/4"),
        ("Seven eighths of a scoop", "7/8"),
    ],
)
def test_a_part_of_a_cup_in_words_sets_the_fraction(
    dispenser: ApplianceModel, text: str, amount: str
) -> None:
    assert parse_instruction(dispenser, text)["amount"] == amount


@pytest.mark.parametrize(
    ("text", "fill"),
    [
        ("Cocoa, half a cup", "half"),
        ("A latte with three quarters of a cup of milk", "three_quarters"),
        ("Tea - a quarter cup only", "quarter"),
    ],
)
def test_a_part_of_a_cup_sets_a_value_named_by_the_part(
    drinks: ApplianceModel, text: str, fill: str
) -> None:
    assert parse_instruction(drinks, text)["fill"] == fill


def test_a_part_of_an_hour_stays_a_duration(drinks: ApplianceModel) -> None:
    goal = parse_instruction(drinks, "Cocoa, and hold it for a quarter of an hour")
    assert goal.get("hold_time") == 15
    assert "fill" not in goal


RINSER = """
appliance: {id: rinser_1, category: parts_rinser, name: "Clearo C2 parts rinser", brand: C}
controls:
  - {id: cycle_button, kind: button, label: "CYCLE"}
  - {id: fill_button, kind: button, label: "FILL"}
variables:
  cycle:
    type: discrete
    values: [gentle, heavy]
  fill:
    type: discrete
    values: [full, half]
actions:
  press_cycle: {control: cycle_button}
  press_fill: {control: fill_button}
features:
  cycle:
    - {actions: [press_cycle], variable: cycle, effect: next}
  fill:
    - {actions: [press_fill], variable: fill, effect: next}
display:
  idle: ""
"""


def test_a_part_of_a_cup_of_something_else_is_no_half_level() -> None:
    """HALF beside FULL is a level ("half fill"), not a scale of parts of a cup: half a cup
    of soap poured in by the user leaves it alone."""
    goal = parse_instruction(loads_model(RINSER), "Heavy cycle with half a cup of soap")
    assert goal == {"cycle": "heavy"}
