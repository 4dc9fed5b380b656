"""Rules of the goal parser checked on small models written for these tests: an interval the
display shows as counts with a unit letter ("W 3d", "d2") takes "every 3 days", "every other
day", "once a week" (and nothing not said "every"); a key that steps a setting and, held,
jumps to one value names that setting, not the value ("pressure 8" is no 1)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

GARDEN = """
appliance: {id: garden_1, category: grow_box, name: "Verda G-1 grow box", brand: V}
controls:
  - {id: water_key, kind: touch, label: "WATER"}
  - {id: again_key, kind: touch, label: "AGAIN"}
  - {id: pause_key, kind: touch, label: "PAUSE"}
variables:
  watering:
    type: discrete
    values: ["off", "1", "2", "3", "7"]
    show: {"off": "W OFF", "1": "W 1d", "2": "W 2d", "3": "W 3d", "7": "W 7d"}
  again:
    type: discrete
    values: ["off", "1", "2"]
    show: {"off": "", "1": "d1", "2": "d2"}
  pause:
    type: discrete
    values: ["off", 24 h, 48 h]
    show: {"off": "", 24 h: "P 24H", 48 h: "P 48H"}
actions:
  press_water: {control: water_key}
  press_again: {control: again_key}
  press_pause: {control: pause_key}
features:
  watering:
    - {actions: [press_water], variable: watering, effect: next}
  again:
    - {actions: [press_again], variable: again, effect: next}
  pause:
    - {actions: [press_pause], variable: pause, effect: next}
display:
  idle: "{watering}"
"""

JET = """
appliance: {id: jet_1, category: flosser, name: "Aqua J-1 flosser", brand: A}
controls:
  - {id: pressure_key, kind: button, label: "PRESSURE"}
  - {id: mode_key, kind: button, label: "MODE"}
variables:
  mode: {type: discrete, values: [clean, soft], show: {clean: "CLEAN", soft: "SOFT"}}
  pressure:
    type: numeric
    wrap: true
    show: "P {value}"
    ranges: [[1, 10, 1]]
    initial: 5
actions:
  press_pressure: {control: pressure_key}
  hold_pressure: {control: pressure_key, skill: hold, seconds: 2}
  press_mode: {control: mode_key}
features:
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  pressure:
    - actions: [press_pressure, hold_pressure]
      variable: pressure
      effect: {press_pressure: next, hold_pressure: {to: 1}}
display:
  idle: "{mode} {pressure}"
"""


def _goal(model: str, text: str) -> dict[str, object]:
    return parse_instruction(loads_model(model), text)


def test_an_interval_shown_with_a_unit_letter_takes_every_so_many_days() -> None:
    assert _goal(GARDEN, "water every 3 days") == {"watering": "3"}
    assert _goal(GARDEN, "water once a week") == {"watering": "7"}
    assert _goal(GARDEN, "again every other day") == {"again": "2"}
    # a span not said "every" is no interval: a pause of two days
    assert _goal(GARDEN, "pause the watering for two days") == {"pause": "48 h"}


def test_a_key_that_steps_a_setting_names_it_not_the_value_it_jumps_to() -> None:
    assert _goal(JET, "soft mode, pressure 8") == {"mode": "soft", "pressure": 8}
    assert _goal(JET, "pressure two") == {"pressure": 2}


SWING = """
appliance: {id: swing_1, category: rocker, name: "Lull R-1 rocker", brand: L}
controls:
  - {id: timer_key, kind: button, label: "TIMER"}
  - {id: pouch_key, kind: button, label: "POUCH"}
variables:
  timer:
    type: discrete
    values: ["off", "8", "15", "30", "60"]
    show: {"off": "t OFF", "8": "t8", "15": "t15", "30": "t30", "60": "t60"}
  pouch:
    type: numeric
    unit: mic
    ranges: [[75, 175, 25]]
actions:
  press_timer: {control: timer_key}
  press_pouch: {control: pouch_key}
features:
  timer:
    - {actions: [press_timer], variable: timer, effect: next}
  pouch:
    - {actions: [press_pouch], variable: pouch, effect: next}
"""


def test_a_timer_of_bare_numbers_counts_minutes_or_hours_whichever_gives_a_value() -> None:
    assert _goal(SWING, "a 15-minute timer") == {"timer": "15"}
    assert _goal(SWING, "set the timer for an hour") == {"timer": "60"}


def test_micrometres_are_a_length_not_minutes() -> None:
    assert _goal(SWING, "175 µm pouches") == {"pouch": 175}
    assert _goal(SWING, "pouches of 100 microns") == {"pouch": 100}
