"""A switch called by a compound the manual uses ("the tail-lamp" for LAMP), a superlative
before a setting's name, levels listed up to MAX, and an AUTO OFF number read as minutes —
on a model written for these tests (a scooter dashboard no suite has)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SCOOTER = """
appliance: {id: scooter_1, category: scooter, name: "Zipp S3 e-scooter dashboard", brand: Z}
controls:
  - {id: lamp_key, kind: button, label: "LAMP"}
  - {id: glow_key, kind: button, label: "GLOW"}
  - {id: drive_key, kind: button, label: "DRIVE"}
  - {id: sleep_key, kind: button, label: "SLEEP"}
variables:
  lamp: {type: discrete, values: ["off", "on"]}
  glow: {type: numeric, ranges: [[1, 4, 1]], initial: 2, wrap: true}
  drive: {type: discrete, values: [SOFT, MID, MAX]}
  sleep: {type: numeric, ranges: [[2, 20, 2]], initial: 10, wrap: true}
actions:
  press_lamp: {control: lamp_key}
  press_glow: {control: glow_key}
  press_drive: {control: drive_key}
  press_sleep: {control: sleep_key}
features:
  lamp:
    - {actions: [press_lamp], variable: lamp, effect: toggle}
  glow:
    - {actions: [press_glow], variable: glow, effect: next}
  drive:
    - {actions: [press_drive], variable: drive, effect: next}
  sleep:
    - {actions: [press_sleep], variable: sleep, effect: next}
"""

MANUAL = "LAMP switches the taillamp on and off. GLOW sets the dashboard glow."


def test_a_compound_the_manual_uses_names_the_switch() -> None:
    goal = parse_instruction(loads_model(SCOOTER), "Put the taillamp on.", MANUAL)
    assert goal == {"lamp": "on"}


def test_a_compound_the_manual_does_not_use_names_nothing() -> None:
    goal = parse_instruction(loads_model(SCOOTER), "The glow at 3, and the sunlamp on.", MANUAL)
    assert "lamp" not in goal


def test_a_superlative_before_the_setting_is_its_top() -> None:
    model = loads_model(SCOOTER)
    assert parse_instruction(model, "The brightest glow, please.") == {"glow": 4}
    assert parse_instruction(model, "The dimmest glow, please.") == {"glow": 1}


def test_levels_up_to_max_are_a_scale() -> None:
    model = loads_model(SCOOTER)
    assert parse_instruction(model, "Drive on the gentlest setting.")["drive"] == "SOFT"
    assert parse_instruction(model, "The maximum drive.")["drive"] == "MAX"


def test_a_number_setting_named_for_sleeping_takes_minutes() -> None:
    model = loads_model(SCOOTER)
    assert parse_instruction(model, "Let it sleep after six minutes.")["sleep"] == 6


LANTERN = """
appliance: {id: lantern_1, category: lantern, name: "Trail L2 camping lantern", brand: T}
controls:
  - {id: beam_key, kind: button, label: "BEAM"}
  - {id: fan_key, kind: button, label: "FAN"}
variables:
  beam: {type: discrete, values: ["off", "on", strobe]}
  fan: {type: discrete, values: [low, high]}
actions:
  press_beam: {control: beam_key}
  press_fan: {control: fan_key}
features:
  beam:
    - {actions: [press_beam], variable: beam, effect: next}
  fan:
    - {actions: [press_fan], variable: fan, effect: next}
"""


def test_a_setting_of_off_on_and_more_takes_its_state_said() -> None:
    model = loads_model(LANTERN)
    assert parse_instruction(model, "Fan high, beam on.") == {"fan": "high", "beam": "on"}
    assert parse_instruction(model, "Please turn off the beam.") == {"beam": "off"}
    assert parse_instruction(model, "Beam strobe.") == {"beam": "strobe"}
