"""Units a selector writes joined ("fl oz", "st:lb") named in words, a selector that lists its
units per mode, and "with the … running" asking for the run — on a model written for these
tests (a luggage and liquid scale no suite has)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SCALE = """
appliance: {id: lugg_1, category: scale, name: "Carry-On hanging scale", brand: C}
controls:
  - {id: on_key, kind: button, label: "ON"}
  - {id: kind_key, kind: button, label: "KIND"}
  - {id: unit_key, kind: button, label: "UNIT"}
  - {id: clock_key, kind: button, label: "CLOCK"}
  - {id: go_key, kind: button, label: "GO"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  kind: {type: discrete, values: [bag, liquid]}
  unit:
    type: discrete
    depends_on: kind
    cases:
      bag: {values: [kg, "st:lb"], initial: kg}
      liquid: {values: [l, fl oz], initial: l}
  clock:
    type: time
    ranges: [["00:00:00", "00:09:00", 60]]
    format: "mm:ss"
  ticking: {type: discrete, values: ["off", "on"]}
actions:
  press_on: {control: on_key}
  press_kind: {control: kind_key}
  press_unit: {control: unit_key}
  press_clock: {control: clock_key}
  press_go: {control: go_key}
features:
  power:
    - {actions: [press_on], variable: power, effect: toggle}
  kind:
    - {actions: [press_kind], variable: kind, effect: next}
  unit:
    - {actions: [press_unit], variable: unit, effect: next}
  clock:
    - {actions: [press_clock], variable: clock, effect: next}
  go:
    - {actions: [press_go], variable: ticking, effect: toggle}
"""


def test_a_joined_unit_named_in_words() -> None:
    model = loads_model(SCALE)
    assert parse_instruction(model, "Show it in stones and pounds.")["unit"] == "st:lb"
    assert parse_instruction(model, "Liquid, read in fluid ounces.")["unit"] == "fl oz"


def test_a_plain_unit_of_a_selector_kept_per_mode() -> None:
    model = loads_model(SCALE)
    assert parse_instruction(model, "Weigh the case in kilograms.")["unit"] == "kg"


def test_with_a_countdown_running_starts_it() -> None:
    model = loads_model(SCALE)
    goal = parse_instruction(model, "Liquid, with a three-minute clock running.")
    assert goal["ticking"] == "on"
