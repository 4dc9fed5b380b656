"""A key believed to step a setting that only brings it up: the panel's + and − adjust it.
Each of the pair is tried, for the setting may sit at the end the first one goes to."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

HOB = """
controls: [{id: level, label: LEVEL}, {id: timer, label: TIMER}, {id: up, label: UP},
           {id: down, label: DOWN}]
variables:
  level: {type: numeric, ranges: [[1, 9, 1]], initial: 9, label: LEVEL{wrap}}
  timer: {type: numeric, ranges: [[0, 12, 1]], unit: h, label: TIMER}
actions:
  press_level: {control: level}
  press_timer: {control: timer}
  press_up: {control: up}
  press_down: {control: down}
features:
{level_steps}
  set_timer:
    - {actions: [press_timer]}
    - {actions: [press_up, press_down], variable: timer, effect: {press_up: next, press_down: prev}}
display: {idle: "READY"}
"""

TRUE_LEVEL = """  set_level:
    - {actions: [press_level]}
    - {actions: [press_up, press_down], variable: level, effect: {press_up: next, press_down: prev}}
"""

READ_LEVEL = """  set_level:
    - {actions: [press_level], variable: level, effect: next}
"""


def test_the_entry_key_s_steppers_are_found_at_the_top_of_the_range() -> None:
    # the level starts at its top, 9: UP leaves it there, DOWN shows the pair at work
    truth = model_from(HOB.replace("{level_steps}", TRUE_LEVEL).replace("{wrap}", ""))
    belief = model_from(HOB.replace("{level_steps}", READ_LEVEL).replace("{wrap}", ", wrap: true"))
    episode, reached = run(truth, belief, {"level": 5})
    assert reached and episode.claimed_success
    assert "press_level only brings level up; press_up, press_down adjust it" in episode.repairs
