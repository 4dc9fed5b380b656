"""Words a panel shows beside every level of a setting, and settings that share a value word.
The model and every sentence are written for these tests (a greenhouse vent controller no suite
has)."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

GREENHOUSE = """
appliance:
  {id: vent_1, category: greenhouse_vent, name: "Glasshaus V2 vent controller", brand: Glasshaus}
controls:
  - {id: vent_key, kind: button, label: "VENT"}
  - {id: close_key, kind: button, label: "AUTO CLOSE"}
  - {id: lamp_key, kind: button, label: "LAMP"}
  - {id: lamptime_key, kind: button, label: "LAMP TIME"}
  - {id: fan_key, kind: button, label: "FAN"}
  - {id: heat_key, kind: button, label: "HEAT"}
variables:
  vent:
    type: discrete
    values: [closed, open]
    show: {closed: "CLOSED", open: "OPEN"}
  auto_close:
    type: discrete
    values: ["off", 5 min, 10 min, 20 min]
  lamp:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "LAMP"}
  lamp_time:
    type: discrete
    values: [1 min, 3 min, 5 min]
  fan_level:
    type: discrete
    values: ["off", low, mid, high]
    show: {"off": "FAN □□□", low: "FAN ■□□", mid: "FAN ■■□", high: "FAN ■■■"}
  heat_level:
    type: discrete
    values: ["off", low, mid, high]
    initial: mid
    show: {"off": "HEAT □□□", low: "HEAT ■□□", mid: "HEAT ■■□", high: "HEAT ■■■"}
actions:
  press_vent: {control: vent_key}
  press_close: {control: close_key}
  press_lamp: {control: lamp_key}
  press_lamptime: {control: lamptime_key}
  press_fan: {control: fan_key}
  press_heat: {control: heat_key}
features:
  vent:
    - {actions: [press_vent], variable: vent, effect: toggle}
  auto_close:
    - {actions: [press_close], variable: auto_close, effect: next}
  lamp:
    - {actions: [press_lamp], variable: lamp, effect: toggle}
  lamp_time:
    - {actions: [press_lamptime], variable: lamp_time, effect: next}
  fan_level:
    - {actions: [press_fan], variable: fan_level, effect: next}
  heat_level:
    - {actions: [press_heat], variable: heat_level, effect: next}
display:
  idle: "{vent}"
"""


@pytest.fixture(scope="module")
def greenhouse() -> ApplianceModel:
    return loads_model(GREENHOUSE)


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("Set the heat to the highest setting", {"heat_level": "high"}),
        ("Heat off and the fan on high", {"heat_level": "off", "fan_level": "high"}),
        ("The fan speed on the low setting, please", {"fan_level": "low"}),
        ("Heat on the high setting", {"heat_level": "high"}),
        ("The heat turned down to the low setting", {"heat_level": "low"}),
    ],
)
def test_a_word_shown_beside_every_level_names_no_one_level(
    greenhouse: ApplianceModel, text: str, goal: dict[str, str]
) -> None:
    """ "HEAT ■■■" names the HEAT setting, not its HIGH: the level is the word said with it."""
    assert parse_instruction(greenhouse, text) == goal


def test_a_value_word_is_not_drawn_to_a_setting_named_in_the_next_act() -> None:
    """ "… on medium and leave the seat at the lowest setting": the seat is named by the act
    after "and leave", not by the one "medium" is said in; it keeps its own "lowest"."""
    text = GREENHOUSE.replace("HEAT", "SEAT").replace("heat", "seat")
    model = loads_model(text.replace("FAN", "WATER").replace("fan", "water"))
    goal = parse_instruction(
        model, "Put the blower on medium and leave the seat at the lowest setting"
    )
    assert goal.get("seat_level") == "low"
