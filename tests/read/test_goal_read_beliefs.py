"""The goal parser on beliefs the offline reader writes, which name things after the panel:
a key's hold read as its own switch beside the setting the key's press adjusts (``frost`` and
``frost_hold``, both labelled FROST), a held key's function said only in the manual's legend
("SPEED button – …; held 3 s it switches turbo mode on or off"), a display's ∞ for a time
without end. Small read-style models written for these tests."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

GREENHOUSE = """
appliance: {id: gh_1, category: greenhouse_heater, name: "read from the manual"}
controls:
  - {id: frost_key, kind: button, label: "FROST"}
  - {id: fan_key, kind: button, label: "FAN"}
variables:
  frost:
    label: FROST
    type: numeric
    unit: "°C"
    ranges: [[1, 10, 1]]
    initial: 4
    wrap: true
  frost_hold:
    label: FROST
    type: discrete
    values: ["off", "on"]
  fan:
    label: FAN
    type: discrete
    values: ["off", "on"]
actions:
  press_frost: {control: frost_key}
  hold_frost: {control: frost_key, skill: hold, seconds: 3.0}
  press_fan: {control: fan_key}
features:
  frost:
    - {actions: [press_frost], variable: frost, effect: next}
  frost_hold:
    - {actions: [hold_frost], variable: frost_hold, effect: toggle}
  fan:
    - {actions: [press_fan], variable: fan, effect: toggle}
"""


def test_a_held_switch_beside_its_keys_setting_takes_the_state_said_after_its_word() -> None:
    model = loads_model(GREENHOUSE)
    goal = parse_instruction(model, "Set the frost limit to 3 degrees with the frost switched on.")
    assert goal == {"frost": 3, "frost_hold": "on"}
    goal = parse_instruction(model, "Turn the frost off, but put its limit at 6 degrees.")
    assert goal == {"frost": 6, "frost_hold": "off"}
    # a state word before a number is a preposition: no switch is asked for
    assert parse_instruction(model, "Frost on 5 degrees.") == {"frost": 5}


BLENDER = """
appliance: {id: bl_1, category: blender, name: "read from the manual"}
controls:
  - {id: speed_key, kind: button, label: "SPEED"}
  - {id: start_key, kind: button, label: "START"}
variables:
  speed:
    label: SPEED
    type: discrete
    values: ["1", "2", "3"]
  speed_hold:
    label: SPEED
    type: discrete
    values: ["off", "on"]
actions:
  press_speed: {control: speed_key}
  hold_speed: {control: speed_key, skill: hold, seconds: 3.0}
features:
  speed:
    - {actions: [press_speed], variable: speed, effect: next}
  speed_hold:
    - {actions: [hold_speed], variable: speed_hold, effect: toggle}
"""

BLENDER_MANUAL = """
Keys

 1 SPEED button - steps through the speeds 1, 2 and 3;
   held for 3 seconds it switches turbo mode on or off.
 2 START button - starts and stops the motor.
"""


def test_a_legend_that_names_the_key_by_its_noun_says_what_its_hold_switches() -> None:
    model = loads_model(BLENDER)
    goal = parse_instruction(model, "Speed 2 and turn turbo mode on.", manual=BLENDER_MANUAL)
    assert goal == {"speed": "2", "speed_hold": "on"}


BOOT_DRYER = """
appliance: {id: bd_1, category: boot_dryer, name: "read from the manual"}
controls:
  - {id: time_key, kind: button, label: "TIME"}
  - {id: heat_key, kind: button, label: "HEAT"}
variables:
  time:
    label: TIME
    type: discrete
    values: ["30", "60", "120", "∞"]
  heat:
    label: HEAT
    type: discrete
    values: ["off", "on"]
actions:
  press_time: {control: time_key}
  press_heat: {control: heat_key}
features:
  time:
    - {actions: [press_time], variable: time, effect: next}
  heat:
    - {actions: [press_heat], variable: heat, effect: toggle}
"""


def test_the_endless_sign_is_said_nonstop_or_continuously() -> None:
    model = loads_model(BOOT_DRYER)
    assert parse_instruction(model, "Dry the boots nonstop with the heat on.") == {
        "time": "∞",
        "heat": "on",
    }
    assert parse_instruction(model, "Let it run continuously.") == {"time": "∞"}


FREEZER = """
appliance: {id: fz_1, category: freezer, name: "read from the manual"}
controls:
  - {id: super_key, kind: button, label: "SUPER"}
variables:
  super: {label: SUPER, type: discrete, values: ["off", "on"]}
  super_frz: {label: SUPER, type: discrete, values: ["off", "on"]}
actions:
  press_super: {control: super_key}
  hold_super: {control: super_key, skill: hold, seconds: 3.0}
features:
  super:
    - {actions: [press_super], variable: super, effect: toggle}
  super_frz:
    - {actions: [hold_super], variable: super_frz, effect: toggle}
"""


def test_a_panel_code_in_a_switchs_name_is_said_spelled_out() -> None:
    model = loads_model(FREEZER)
    assert parse_instruction(model, "Turn on super freeze.") == {"super_frz": "on"}
    assert parse_instruction(model, "Super on.") == {"super": "on"}
