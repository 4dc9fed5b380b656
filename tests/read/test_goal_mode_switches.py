"""A mode's values read as one on/off switch each: "holiday mode" is the VACATION switch,
"energy-saving mode" the ECO switch, and "eco" is ECO's own switch even where a second function
held on the same key (AWAY behind a held ECO) wears the ECO label. Checked on a wine-cellar
panel written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

CELLAR = """
appliance: {id: cellar_1, category: wine_cooler, name: "Cava C8 cellar", brand: C}
controls:
  - {id: temp_button, kind: button, label: "TEMP"}
  - {id: eco_button, kind: button, label: "ECO"}
  - {id: vacation_button, kind: button, label: "VACATION"}
variables:
  temp:
    type: numeric
    ranges: [[5, 18, 1]]
    unit: "°C"
  boost:
    label: "ECO"
    type: discrete
    values: ["off", "on"]
  eco:
    label: "ECO"
    type: discrete
    values: ["off", "on"]
  vacation:
    type: discrete
    values: ["off", "on"]
actions:
  press_temp: {control: temp_button}
  hold_eco: {control: eco_button, skill: hold, seconds: 3}
  press_eco: {control: eco_button}
  press_vacation: {control: vacation_button}
features:
  temp:
    - {actions: [press_temp], variable: temp, effect: next}
  boost:
    - {actions: [hold_eco], variable: boost, effect: toggle}
  eco:
    - {actions: [press_eco], variable: eco, effect: toggle}
  vacation:
    - {actions: [press_vacation], variable: vacation, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def cellar() -> ApplianceModel:
    return loads_model(CELLAR)


@pytest.mark.parametrize(
    "text", ["Twelve degrees and holiday mode, we're off for a month.", "Put it in holiday mode."]
)
def test_holiday_mode_is_the_vacation_switch(cellar: ApplianceModel, text: str) -> None:
    assert parse_instruction(cellar, text).get("vacation") == "on"


def test_energy_saving_mode_is_the_eco_switch(cellar: ApplianceModel) -> None:
    goal = parse_instruction(cellar, "Energy-saving mode please, at 10 degrees.")
    assert goal.get("eco") == "on"
    assert "boost" not in goal


def test_eco_names_its_own_switch_not_the_held_one(cellar: ApplianceModel) -> None:
    goal = parse_instruction(cellar, "Put it on eco at 14 degrees.")
    assert goal.get("eco") == "on"
    assert "boost" not in goal


def test_a_holiday_is_not_a_mode_unless_said_so(cellar: ApplianceModel) -> None:
    assert "vacation" not in parse_instruction(cellar, "Put the bottles away at 8 degrees.")
