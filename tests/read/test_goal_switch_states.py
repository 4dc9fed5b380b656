"""A state said right after a switch's name ("keep warm on", "with the fan running") is that
switch's state, not a request to power the appliance; "keep it running" still is. Checked on
a food warmer written for these tests (no start key: it works while it is on; its brand name
says WARM, as the baby bottle warmer's does)."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

WARMER = """
appliance: {id: warmer_1, category: food_warmer, name: "Cosy WarmMate C3 food warmer", brand: C}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: level_button, kind: button, label: "LEVEL"}
  - {id: warm_button, kind: button, label: "KEEP WARM"}
  - {id: fan_button, kind: button, label: "FAN"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  level:
    type: discrete
    values: ["1", "2", "3"]
  keep_warm:
    type: discrete
    values: ["off", "on"]
  fan:
    type: discrete
    values: ["off", "on"]
actions:
  press_power: {control: power_button}
  press_level: {control: level_button}
  press_warm: {control: warm_button}
  press_fan: {control: fan_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  level:
    - {actions: [press_level], variable: level, effect: next}
  keep_warm:
    - {actions: [press_warm], variable: keep_warm, effect: toggle}
  fan:
    - {actions: [press_fan], variable: fan, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def warmer() -> ApplianceModel:
    return loads_model(WARMER)


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("Soup on level 2, keep warm on.", {"level": "2", "keep_warm": "on"}),
        ("Level 3 with the fan running.", {"level": "3", "fan": "on"}),
    ],
)
def test_a_state_after_a_switchs_name_is_the_switchs(
    warmer: ApplianceModel, text: str, goal: dict[str, str]
) -> None:
    assert parse_instruction(warmer, text) == goal


def test_the_appliance_kept_running_is_still_powered(warmer: ApplianceModel) -> None:
    assert parse_instruction(warmer, "Level 3, and keep it running.")["power"] == "on"
