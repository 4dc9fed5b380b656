"""Probing for a guard never locks the panel: a key ignored without a sign is no reason to put
a child lock on and see whether the key works then.
"""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

HEATER = """
controls: [{id: power, label: POWER}, {id: level, label: LEVEL}, {id: timer, label: TIMER},
           {id: up, label: UP}, {id: down, label: DOWN}, {id: lock, label: LOCK}]
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "{level}"}}
  level: {type: numeric, ranges: [[40, 70, 10]], initial: 50, unit: "%", show: "{value}",
          wrap: true}
  timer: {type: numeric, ranges: [[0, 12, 1]], unit: h, label: TIMER}
  child_lock: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "LK"}}
actions:
  press_power: {control: power}
  press_level: {control: level}
  press_timer: {control: timer}
  press_up: {control: up}
  press_down: {control: down}
  hold_lock: {control: lock, skill: hold, seconds: 3}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
{level_steps}
  set_timer:
    - {actions: [press_timer]}
    - {actions: [press_up, press_down], variable: timer, effect: {press_up: next, press_down: prev}}
  child_lock:
    - {actions: [hold_lock], variable: child_lock, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], hide: true}
  - {name: child lock, when: {child_lock: "on"}, only: [hold_lock], display: "LK"}
display: {idle: "{level}", indicators: [child_lock]}
"""

TRUE_LEVEL = """  set_level:
    - {actions: [press_level]}
    - {actions: [press_up, press_down], variable: level, effect: {press_up: next, press_down: prev}}
"""

# the reader took LEVEL for a key that steps the level on its own
READ_LEVEL = """  set_level:
    - {actions: [press_level], variable: level, effect: next}
"""


def test_a_key_ignored_without_a_sign_is_not_probed_by_locking_the_panel() -> None:
    truth = model_from(HEATER.replace("{level_steps}", TRUE_LEVEL))
    belief = model_from(HEATER.replace("{level_steps}", READ_LEVEL))
    episode, reached = run(truth, belief, {"power": "on", "level": 60})
    assert not any(e.action == "hold_lock" for e in episode.trace)
    assert reached and episode.claimed_success
