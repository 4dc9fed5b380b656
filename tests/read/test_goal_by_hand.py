"""A setting the user says they will set themselves ("I'll choose the speed myself") is set in
the MANUAL case of the mode it depends on; the automatic cases choose it on their own. Checked on
a pool pump written for these tests, whose pump speed exists only in MANUAL."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

PUMP = """
appliance: {id: pump_1, category: pool_pump, name: "Clarion PP-3 pool pump", brand: C}
controls:
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
  - {id: start_button, kind: button, label: "START"}
variables:
  mode:
    type: discrete
    values: [auto, manual, night]
    show: {auto: "AUTO", manual: "MAN", night: "NIGHT"}
  pump_speed:
    type: numeric
    depends_on: mode
    cases:
      manual: {ranges: [[1, 4, 1]], initial: 2}
  running:
    type: discrete
    values: ["off", "on"]
actions:
  press_mode: {control: mode_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_start: {control: start_button}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  pump_speed:
    - {actions: [press_up], variable: pump_speed, effect: next}
    - {actions: [press_down], variable: pump_speed, effect: prev}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def pump() -> ApplianceModel:
    return loads_model(PUMP)


@pytest.mark.parametrize(
    "text",
    [
        "I'd rather pick the pump speed myself - speed 3",
        "Speed 3; we'll set the speed ourselves.",
        "Run it at my own speed: 3",
    ],
)
def test_a_setting_set_by_hand_is_in_manual(pump: ApplianceModel, text: str) -> None:
    goal = parse_instruction(pump, text)
    assert goal["mode"] == "manual"
    assert goal["pump_speed"] == 3


@pytest.mark.parametrize(
    "text",
    ["Speed 3 please", "Speed 3, and I'll start it myself", "Night mode; I'll check it myself"],
)
def test_no_manual_case_unless_the_setting_is_said_by_hand(pump: ApplianceModel, text: str) -> None:
    assert parse_instruction(pump, text).get("mode") in (None, "night")


@pytest.mark.parametrize(
    "text",
    [
        "I don't want to pick the speed myself, let it choose",
        "I'd rather not set the speed myself",
        "No need for me to set the speed myself",
        "Let it decide; I won't choose the speed myself",
    ],
)
def test_a_setting_not_set_by_hand_leaves_the_mode(pump: ApplianceModel, text: str) -> None:
    """A denial before 'myself' says the user will NOT set it: no MANUAL case from that."""
    assert parse_instruction(pump, text).get("mode") != "manual"
