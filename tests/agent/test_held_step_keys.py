"""A key pressed and held in the same step (▼ one value, ▼ held ten) is that setting's
stepping key: a screen misread as another setting's ("20 TIME FAN LO" taken for the fan's)
does not move one touch of it to the other setting's procedure."""

from __future__ import annotations

from apbot.model.load import loads_model
from tests.helpers import run_checked as run

# a rowing machine's panel: a target (minutes or distance) ▲ / ▼ step, held: ten at once
TRUTH = """
appliance: {id: rower_truth, category: rower}
controls:
  - {id: goal_key, label: GOAL}
  - {id: prog_key, label: PROG}
  - {id: fan_key, label: FAN}
  - {id: up_key, label: "▲"}
  - {id: down_key, label: "▼"}
variables:
  prog:
    type: discrete
    values: [manual, hill, interval]
    show: {manual: P0, hill: P1, interval: P2}
  countdown:
    type: discrete
    values: [time, distance]
    show: {time: "TIME", distance: "DIST"}
  target:
    type: numeric
    depends_on: countdown
    wrap: false
    cases:
      time: {ranges: [[5, 99, 1]], initial: 30}
      distance: {ranges: [[1, 40, 1]], initial: 5}
    show: "{value}"
  fan:
    type: discrete
    values: ["off", lo, hi]
    show: {"off": "", lo: "FAN LO", hi: "FAN HI"}
actions:
  press_goal: {control: goal_key}
  press_prog: {control: prog_key}
  press_fan: {control: fan_key}
  press_up: {control: up_key}
  press_down: {control: down_key}
  hold_up: {control: up_key, skill: hold, seconds: 2}
  hold_down: {control: down_key, skill: hold, seconds: 2}
features:
  set_prog: [{actions: [press_prog], variable: prog, effect: next}]
  set_goal: [{actions: [press_goal], variable: countdown, effect: next}]
  set_fan: [{actions: [press_fan], variable: fan, effect: next}]
  set_target:
    - actions: [press_up, press_down, hold_up, hold_down]
      variable: target
      effect: {press_up: next, press_down: prev, hold_up: {skip: 10}, hold_down: {skip: -10}}
display:
  idle: "{prog} {target}"
  indicators: [countdown, fan]
"""


def _belief() -> str:
    """As read: no display templates, the target's and fan's screens under their labels."""
    return (
        TRUTH.replace('show: "{value}"', "label: TARGET")
        .replace('show: {"off": "", lo: "FAN LO", hi: "FAN HI"}', "label: FAN")
        .replace('show: {time: "TIME", distance: "DIST"}', "label: GOAL")
        .replace('idle: "{prog} {target}"', 'idle: "{prog}"')
        .replace("indicators: [countdown, fan]", "indicators: []")
    )


def test_a_pressed_and_held_key_stays_with_its_setting() -> None:
    goal = {"prog": "hill", "fan": "lo", "target": 20}
    episode, reached = run(loads_model(TRUTH), loads_model(_belief()), goal)
    assert reached and episode.claimed_success
    assert not any("belongs to set_fan" in r for r in episode.repairs)
