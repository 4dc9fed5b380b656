""" "Myself" on a model that does not say which mode a setting depends on — as a belief read
from a manual seldom does: the one selector with a MANUAL value beside automatic ones is set to
MANUAL when the user says they set a setting (or the quantity it measures) themselves. Checked
on a greenhouse heater written for these tests, with no ``depends_on`` anywhere."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

HEATER = """
appliance: {id: heater_1, category: greenhouse_heater, name: "Verdant GH-4 heater", brand: V}
controls:
  - {id: prog_button, kind: button, label: "PROG"}
  - {id: fan_button, kind: button, label: "FAN"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
  - {id: clock_button, kind: button, label: "CLOCK"}
  - {id: fan_down_button, kind: button, label: "FAN -"}
  - {id: clock_down_button, kind: button, label: "CLOCK -"}
  - {id: start_button, kind: button, label: "START"}
variables:
  prog:
    type: discrete
    values: [frost, seedling, manual]
    show: {frost: "FRO", seedling: "SEED", manual: "MAN"}
  fan:
    type: numeric
    ranges: [[1, 4, 1]]
    initial: 2
  heat:
    type: numeric
    unit: "°C"
    ranges: [[5, 30, 1]]
    initial: 12
  clock:
    type: time
    ranges: [["00:00:00", "23:59:00", "00:01:00"]]
    initial: "12:00:00"
  running:
    type: discrete
    values: ["off", "on"]
actions:
  press_prog: {control: prog_button}
  press_fan: {control: fan_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_clock: {control: clock_button}
  press_fan_down: {control: fan_down_button}
  press_clock_down: {control: clock_down_button}
  press_start: {control: start_button}
features:
  prog:
    - {actions: [press_prog], variable: prog, effect: next}
  fan:
    - {actions: [press_fan], variable: fan, effect: next}
    - {actions: [press_fan_down], variable: fan, effect: prev}
  heat:
    - {actions: [press_up], variable: heat, effect: next}
    - {actions: [press_down], variable: heat, effect: prev}
  clock:
    - {actions: [press_clock], variable: clock, effect: next}
    - {actions: [press_clock_down], variable: clock, effect: prev}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def heater() -> ApplianceModel:
    return loads_model(HEATER)


@pytest.mark.parametrize(
    "text",
    [
        "I'd like to pick the fan myself - fan 3",
        "We'll choose the temperatures ourselves: 18 degrees",
        "My own fan setting of 4, please",
    ],
)
def test_a_setting_set_by_hand_picks_the_manual_value(heater: ApplianceModel, text: str) -> None:
    assert parse_instruction(heater, text).get("prog") == "manual"


@pytest.mark.parametrize(
    "text",
    [
        "Fan 3 please",
        "Fan 3, and I'll start it myself",
        "I'll set the clock myself, it's 7:30",
        "Seedling programme; I'll check the fan myself",
    ],
)
def test_no_manual_value_unless_a_setting_is_set_by_hand(heater: ApplianceModel, text: str) -> None:
    assert parse_instruction(heater, text).get("prog") in (None, "seedling")
