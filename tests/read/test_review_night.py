"""Goal rules of the 6 December night, narrowed after a review found them setting values an
ordinary sentence never asked for (each model and sentence written for these tests)."""

from __future__ import annotations

from apbot.read.goal import parse_instruction
from tests.helpers import model_from

CLOCK = """
controls: [{id: power}, {id: alarm}, {id: ok}, {id: light}]
variables:
  power: {type: discrete, values: ["off", "on"], label: POWER}
  alarm_hour: {type: numeric, ranges: [[0, 23, 1]], initial: 7, wrap: true, label: HOUR}
  alarm: {type: discrete, values: ["off", "on"], label: ALARM}
  glow: {type: discrete, values: [low, medium, high], label: GLOW}
actions:
  press_power: {control: power}
  press_alarm: {control: alarm}
  press_ok: {control: ok}
  press_light: {control: light}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_alarm:
    - {actions: [press_alarm], variable: alarm_hour, effect: next}
    - {actions: [press_ok], variable: alarm, effect: {to: "on"}}
  set_glow: [{actions: [press_light], variable: glow, effect: next}]
"""


def test_a_switch_said_off_is_not_armed_by_its_setting_s_confirmation() -> None:
    model = model_from(CLOCK, check=False)
    assert parse_instruction(model, "Set the alarm hour to 6.")["alarm"] == "on"
    goal = parse_instruction(model, "Set the alarm hour to 6 but leave the alarm off.")
    assert goal.get("alarm") != "on"


def test_a_superlative_of_little_degree_is_the_least() -> None:
    model = model_from(CLOCK, check=False)
    assert parse_instruction(model, "The mildest glow, please.")["glow"] == "low"
    assert parse_instruction(model, "Give me the faintest glow.")["glow"] == "low"
