"""Everyday words for value names: "energy-saving" for ECONOMY, "recovery" for REPAIR,
"freshen up" for REFRESH. Checked on a spa heater and a charger written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SPA = """
appliance: {id: spa_1, category: spa, name: "Bubbla S-1 spa", brand: B}
controls:
  - {id: heat_button, kind: button, label: "HEAT MODE"}
  - {id: prog_button, kind: button, label: "PROGRAMME"}
variables:
  heat_mode:
    type: discrete
    values: [standard, economy, sleep]
  programme:
    type: discrete
    values: [normal, repair, refresh]
actions:
  press_heat: {control: heat_button}
  press_prog: {control: prog_button}
features:
  heat_mode:
    - {actions: [press_heat], variable: heat_mode, effect: next}
  programme:
    - {actions: [press_prog], variable: programme, effect: next}
display:
  idle: ""
"""


def test_everyday_words_for_value_names() -> None:
    spa = loads_model(SPA)
    assert parse_instruction(spa, "Use the energy-saving heating") == {"heat_mode": "economy"}
    assert parse_instruction(spa, "the recovery programme") == {"programme": "repair"}
    assert parse_instruction(spa, "Freshen up the water") == {"programme": "refresh"}
