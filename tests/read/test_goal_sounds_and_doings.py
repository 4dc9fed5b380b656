"""Four ways people and panels name things, checked on small models written for these tests:

- a key whose label is its setting's name, held to go to one value, names the setting, not the
  value ("pressure 8" on a jet whose PRESSURE held returns to P 1);
- a sound level's MUTE is its none and "loud" its HIGH ("sound off", "no beeping", "silent",
  "loud beeps");
- the longer word a one-word name cuts short names an off level ("the heater off" for HEAT);
- on a model with no running state, the one switch named for a doing (PRINTING) is it.
"""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

JET = """
appliance: {id: jet_1, category: garden_jet, name: "Spray J1 garden jet", brand: S}
controls:
  - {id: pressure_button, kind: button, label: "PRESSURE"}
variables:
  pressure:
    type: numeric
    ranges: [[1, 10, 1]]
    initial: 5
actions:
  press_pressure: {control: pressure_button}
  hold_pressure: {control: pressure_button, skill: hold, seconds: 2}
features:
  pressure:
    - actions: [press_pressure, hold_pressure]
      variable: pressure
      effect: {press_pressure: next, hold_pressure: {to: 1}}
display:
  idle: ""
"""

DOOR = """
appliance: {id: door_1, category: door_keypad, name: "Keyo D1 door keypad", brand: K}
controls:
  - {id: volume_button, kind: button, label: "BEEPER VOLUME"}
  - {id: heat_button, kind: button, label: "HEAT"}
variables:
  beeper_volume:
    type: discrete
    values: [mute, low, high]
    initial: low
  heat:
    type: discrete
    values: ["off", eco, full]
    initial: eco
actions:
  press_volume: {control: volume_button}
  press_heat: {control: heat_button}
features:
  volume:
    - {actions: [press_volume], variable: beeper_volume, effect: next}
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
display:
  idle: ""
"""

PRINTER = """
appliance: {id: printer_1, category: tag_printer, name: "Taggo T1 tag printer", brand: T}
controls:
  - {id: style_button, kind: button, label: "STYLE"}
  - {id: print_button, kind: button, label: "PRINT"}
variables:
  style:
    type: discrete
    values: [normal, bold]
  printing:
    type: discrete
    values: ["off", "on"]
actions:
  press_style: {control: style_button}
  press_print: {control: print_button}
features:
  style:
    - {actions: [press_style], variable: style, effect: next}
  print:
    - {actions: [press_print], variable: printing, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def jet() -> ApplianceModel:
    return loads_model(JET)


@pytest.fixture(scope="module")
def door() -> ApplianceModel:
    return loads_model(DOOR)


@pytest.fixture(scope="module")
def printer() -> ApplianceModel:
    return loads_model(PRINTER)


@pytest.mark.parametrize(("text", "level"), [("Pressure 8.", 8), ("pressure three", 3)])
def test_a_key_named_as_its_setting_names_no_value(
    jet: ApplianceModel, text: str, level: int
) -> None:
    assert parse_instruction(jet, text) == {"pressure": level}


@pytest.mark.parametrize(
    ("text", "volume"),
    [
        ("Sound off.", "mute"),
        ("No beeping, please.", "mute"),
        ("Keep it silent.", "mute"),
        ("Loud beeps.", "high"),
        ("A loud beeper.", "high"),
    ],
)
def test_a_sound_level_is_muted_and_loud(door: ApplianceModel, text: str, volume: str) -> None:
    assert parse_instruction(door, text).get("beeper_volume") == volume


@pytest.mark.parametrize("text", ["Turn the heater off.", "Heater off, please."])
def test_the_longer_word_names_the_off_level(door: ApplianceModel, text: str) -> None:
    assert parse_instruction(door, text).get("heat") == "off"


@pytest.mark.parametrize(
    ("text", "printing"),
    [
        ("Bold, and start printing.", "on"),
        ("Bold text, start now.", "on"),
        ("Bold text, and print.", "on"),
        ("Bold text, but don't print yet.", "off"),
        ("Bold text.", None),
    ],
)
def test_a_switch_named_for_a_doing_is_the_running_state(
    printer: ApplianceModel, text: str, printing: str | None
) -> None:
    assert parse_instruction(printer, text).get("printing") == printing
