"""Two values of one setting said together name its value for both ("flash and sound" is
SOUND+FLASH, "the rain head and the handset" BOTH); one of them alone names itself. Small
models written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

BELL = """
appliance: {id: bell_1, category: door_bell, name: "Dong B-1 bell", brand: D}
controls:
  - {id: alert_key, kind: button, label: "ALERT"}
  - {id: outlet_key, kind: button, label: "OUTLET"}
variables:
  alert:
    type: discrete
    values: [sound, flash, both]
    show: {sound: "SOUND", flash: "FLASH", both: "SOUND+FLASH"}
actions:
  press_alert: {control: alert_key}
features:
  alert:
    - {actions: [press_alert], variable: alert, effect: next}
"""

SHOWER = """
appliance: {id: shower_1, category: shower, name: "Rain S-1 shower", brand: R}
controls:
  - {id: outlet_key, kind: button, label: "OUTLET"}
variables:
  outlet:
    type: discrete
    values: [overhead, handset, all]
    show: {overhead: "RAIN", handset: "HAND", all: "RAIN HAND"}
actions:
  press_outlet: {control: outlet_key}
features:
  outlet:
    - {actions: [press_outlet], variable: outlet, effect: next}
"""


def test_two_values_said_together_name_the_value_for_both() -> None:
    assert parse_instruction(loads_model(BELL), "flash and sound together") == {"alert": "both"}
    shower = loads_model(SHOWER)
    assert parse_instruction(shower, "through the rain head and the handset") == {"outlet": "all"}


def test_one_value_alone_names_itself() -> None:
    assert parse_instruction(loads_model(BELL), "just the flash, please") == {"alert": "flash"}
    assert parse_instruction(loads_model(SHOWER), "the handset only") == {"outlet": "handset"}


LAMP = """
appliance: {id: lamp_1, category: tank_light, name: "Reef L-1 light", brand: R}
controls:
  - {id: kind_key, kind: button, label: "TYPE"}
  - {id: colour_key, kind: button, label: "COLOUR"}
variables:
  kind: {type: discrete, values: [white and blue, red]}
  colour: {type: discrete, values: [white, blue, white and blue]}
actions:
  press_kind: {control: kind_key}
  press_colour: {control: colour_key}
features:
  kind:
    - {actions: [press_kind], variable: kind, effect: next}
  colour:
    - {actions: [press_colour], variable: colour, effect: next}
"""


def test_two_values_read_whole_as_another_settings_value_name_no_both() -> None:
    goal = parse_instruction(loads_model(LAMP), "100 % in white and blue")
    assert len([v for v in goal.values() if v == "white and blue"]) == 1
