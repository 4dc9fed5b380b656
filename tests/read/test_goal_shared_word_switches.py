"""Two switches that share a word (TURBO COOL, TURBO FREEZE on one TURBO key): the shared word
with the next one names that switch only (goal_switches). A model written for this test."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

CHEST = """
appliance: {id: chest_9, category: chest_freezer, name: "Frosta CF-9 chest cooler", brand: F}
controls:
  - {id: turbo_key, kind: touch, label: "TURBO"}
variables:
  turbo_cool: {type: discrete, values: ["off", "on"]}
  turbo_freeze: {type: discrete, values: ["off", "on"]}
actions:
  press_turbo: {control: turbo_key}
  hold_turbo: {control: turbo_key, skill: hold, seconds: 3}
features:
  turbo_cool:
    - {actions: [press_turbo], variable: turbo_cool, effect: toggle}
  turbo_freeze:
    - {actions: [hold_turbo], variable: turbo_freeze, effect: toggle}
display:
  idle: "{turbo_cool}"
"""


def test_the_shared_word_and_the_next_name_one_switch() -> None:
    goal = parse_instruction(loads_model(CHEST), "Switch on turbo freeze for the new fish.")
    assert goal == {"turbo_freeze": "on"}
