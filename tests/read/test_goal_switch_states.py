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


# a smoker whose numbered key legend says what its CIRC key switches (the user names the fan),
# and whose automatic switch-off a read belief names by the manual's words
SMOKER = """
appliance: {id: smoker_9, category: smoker, name: "Emberline S9 electric smoker", brand: E}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: level_button, kind: button, label: "LEVEL"}
  - {id: circ_button, kind: button, label: "CIRC"}
  - {id: off_button, kind: button, label: "AUTO OFF"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  level:
    type: discrete
    values: ["1", "2", "3"]
  circ:
    type: discrete
    values: ["off", "on"]
  auto_switch_off:
    type: discrete
    values: ["off", "on"]
actions:
  press_power: {control: power_button}
  press_level: {control: level_button}
  press_circ: {control: circ_button}
  hold_auto_off: {control: off_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  level:
    - {actions: [press_level], variable: level, effect: next}
  circ:
    - {actions: [press_circ], variable: circ, effect: toggle}
  auto_switch_off:
    - {actions: [hold_auto_off], variable: auto_switch_off, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
display:
  idle: ""
"""
SMOKER_MANUAL = """Emberline S9 electric smoker

KEYS
  ①  POWER       switches the smoker on or off
  ②  LEVEL       smoke level 1 → 2 → 3
  ③  CIRC        Convection fan on / off (FAN in the display).
"""


@pytest.fixture(scope="module")
def smoker() -> ApplianceModel:
    return loads_model(SMOKER)


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("Level 2 with the convection fan on.", {"level": "2", "circ": "on"}),
        (
            "Level 3, the fan running, and switch it on.",
            {"level": "3", "circ": "on", "power": "on"},
        ),
        ("Level 1, the fan on the lowest speed.", {"level": "1"}),
    ],
)
def test_a_numbered_legends_thing_with_its_state_names_the_switch(
    smoker: ApplianceModel, text: str, goal: dict[str, str]
) -> None:
    """The legend led by ③ names the CIRC switch the fan; "the fan on" said as a state sets it,
    "the fan on the lowest speed" is no state of it."""
    assert parse_instruction(smoker, text, SMOKER_MANUAL) == goal


def test_the_verb_of_switching_is_no_word_of_an_auto_switch_off(smoker: ApplianceModel) -> None:
    assert parse_instruction(smoker, "Switch the smoker on, level 2.") == {
        "power": "on",
        "level": "2",
    }


@pytest.mark.parametrize(
    "text", ["Level 2, never with the fan running.", "Level 3, not with the fan on."]
)
def test_a_legends_thing_with_its_state_negated_sets_no_switch(
    smoker: ApplianceModel, text: str
) -> None:
    """The state said of the legend's thing is negated: the user does not ask for the fan."""
    assert "circ" not in parse_instruction(smoker, text, SMOKER_MANUAL)


def test_no_need_for_the_legends_thing_on_sets_no_switch(smoker: ApplianceModel) -> None:
    assert parse_instruction(smoker, "Level 2 - no need for the fan on.", SMOKER_MANUAL) == {
        "level": "2"
    }
