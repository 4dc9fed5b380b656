"""A state the appliance is to reach on its own ("shut itself after 2 minutes") or the tail of
another setting's two-word name ("auto-shut") is not that state asked for now (goal_names).
A model written for these tests: a gate opener with the gate OPEN / SHUT and an AUTO SHUT
delay."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

GATE = """
appliance: {id: gate_9, category: gate_opener, name: "Porta GO-9 gate opener", brand: P}
controls:
  - {id: gate_button, kind: button, label: "GATE"}
  - {id: delay_button, kind: button, label: "AUTO SHUT"}
variables:
  gate:
    type: discrete
    values: [shut, open]
  auto_shut:
    type: discrete
    values: ["off", 1 min, 2 min, 5 min]
    label: "AUTO SHUT"
actions:
  press_gate: {control: gate_button}
  press_delay: {control: delay_button}
features:
  gate:
    - {actions: [press_gate], variable: gate, effect: next}
  auto_shut:
    - {actions: [press_delay], variable: auto_shut, effect: next}
display:
  idle: "{gate}"
"""


def test_shut_itself_after_a_while_is_the_delay_not_the_gate() -> None:
    goal = parse_instruction(loads_model(GATE), "Have the gate shut itself after 5 minutes")
    assert goal == {"auto_shut": "5 min"}


def test_the_tail_of_a_two_word_name_is_that_setting() -> None:
    goal = parse_instruction(loads_model(GATE), "Auto-shut after two minutes")
    assert goal == {"auto_shut": "2 min"}
