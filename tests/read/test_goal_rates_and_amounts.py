"""Quantities said in another unit than the setting's and amounts said instead of a legend's
adjective, on a small ball-thrower written for these tests: kilometres an hour on a mph dial,
balls a minute on a seconds-between-balls feed, "a touch of topspin" for LIGHT TOPSPIN, and an
end of the feed the manual marks in a bracket after a quantity ("2 s (the fastest feed)")."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

THROWER = """
appliance: {id: thrower_1, category: pitching_machine, name: "Pitcha 9 thrower", brand: P}
controls:
  - {id: speed_key, kind: button, label: "SPEED"}
  - {id: feed_key, kind: button, label: "FEED"}
  - {id: spin_key, kind: button, label: "SPIN"}
variables:
  speed: {type: numeric, unit: " mph", ranges: [[30, 70, 5]], initial: 40, wrap: true}
  feed: {type: numeric, unit: "s", ranges: [[3, 12, 1]], initial: 6, wrap: true}
  spin: {type: discrete, values: [S2, S1, "0", U1, U2], initial: "0", wrap: true}
actions:
  press_speed: {control: speed_key}
  press_feed: {control: feed_key}
  press_spin: {control: spin_key}
features:
  speed:
    - {actions: [press_speed], variable: speed, effect: next}
  feed:
    - {actions: [press_feed], variable: feed, effect: next}
  spin:
    - {actions: [press_spin], variable: spin, effect: next}
"""

MANUAL = """
Speed is shown in mph. 40 km/h is 25 mph, 80 km/h is 50 mph.

Spin
   S2   heavy slice
   S1   light slice
   0    flat
   U1   light topspin
   U2   heavy topspin

Feed: the seconds between two balls, from 3 seconds (the fastest
feed) to 12 seconds (the slowest).

   Seconds           3    4    5    6    10   12
   Balls per minute  20   15   12   10   6    5
"""


def _said(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(THROWER), sentence, MANUAL)


def test_kilometres_an_hour_on_a_mph_dial() -> None:
    assert _said("eighty kilometres an hour") == {"speed": 50}
    assert _said("sixty-five miles an hour") == {"speed": 65}


def test_balls_a_minute_on_a_seconds_between_feed() -> None:
    assert _said("fifteen balls a minute") == {"feed": 4}


def test_an_amount_said_for_the_legends_adjective() -> None:
    assert _said("a touch of topspin") == {"spin": "U1"}
    assert _said("lots of slice at 45 mph") == {"spin": "S2", "speed": 45}


def test_an_end_marked_after_a_quantity_across_lines() -> None:
    assert _said("the quickest feed") == {"feed": 3}
    assert _said("the slowest feed") == {"feed": 12}


PRESS = """
appliance: {id: press_9, category: heat_press, name: "Flatt heat press", brand: F}
controls:
  - {id: digit_key, kind: button, label: "DIGIT"}
  - {id: time_key, kind: button, label: "TIME"}
  - {id: buzz_key, kind: button, label: "BUZZER"}
variables:
  digit: {type: discrete, values: [ones, tens]}
  time: {type: numeric, unit: "s", ranges: [[0, 90, 10]], initial: 20, wrap: true}
  buzzer: {type: discrete, values: ["on", "off"], show: {"on": "", "off": "MUTE"}}
actions:
  press_digit: {control: digit_key}
  press_time: {control: time_key}
  press_buzz: {control: buzz_key}
features:
  digit:
    - {actions: [press_digit], variable: digit, effect: next}
  time:
    - {actions: [press_time], variable: time, effect: next}
  buzzer:
    - {actions: [press_buzz], variable: buzzer, effect: toggle}
"""


def test_silence_said_switches_the_buzzer_off() -> None:
    model = loads_model(PRESS)
    assert parse_instruction(model, "press for thirty seconds, silently") == {
        "time": 30,
        "buzzer": "off",
    }
    assert parse_instruction(model, "keep it quiet") == {"buzzer": "off"}


def test_a_number_said_is_no_place_of_a_digit_cursor() -> None:
    model = loads_model(PRESS)
    assert parse_instruction(model, "a one-minute press") == {"time": 60}
    assert parse_instruction(model, "for ten seconds") == {"time": 10}
