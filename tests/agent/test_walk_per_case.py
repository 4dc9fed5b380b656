"""A setting whose range depends on another (a per-mode range) is walked once per mode: a walk
in one mode says nothing of another mode's values, so a goal value the belief lacks in the
goal's mode is walked for there even after a walk in another mode."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

# A styling iron: each mode keeps its own heat range (gentle 130 … 170, normal 150 … 200, in
# 10s); the mode shows as a word beside the heat.
KEYS = """
controls: [{id: power, label: POWER}, {id: mode, label: MODE}, {id: up, label: "+"},
           {id: down, label: "-"}]
actions: {hold_power: {control: power}, press_mode: {control: mode}, press_up: {control: up},
          press_down: {control: down}}
features:
  power: [{actions: [hold_power], variable: power, effect: toggle}]
  mode: [{actions: [press_mode], variable: mode, effect: next}]
  heat:
    - {actions: [press_up, press_down], variable: heat,
       effect: {press_up: next, press_down: prev}}
guards: [{when: {power: "off"}, only: [hold_power], hide: true}]
display: {indicators: [mode]}
"""
TRUTH = (
    KEYS
    + """
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": ""}}
  mode: {type: discrete, values: [gentle, normal], initial: normal,
         show: {gentle: GENTLE, normal: NORMAL}}
  heat: {type: numeric, depends_on: mode, show: "{value} C",
         cases: {gentle: {ranges: [[130, 170, 10]], initial: 150},
                 normal: {ranges: [[150, 200, 10]], initial: 180}}}
"""
)
# The belief read each mode's range from a table of suggestions (one or two values each, a
# guessed step) and the starting mode wrong.
BELIEF = (
    KEYS
    + """
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": ""}}
  mode: {type: discrete, values: [gentle, normal], initial: gentle,
         show: {gentle: GENTLE, normal: NORMAL}}
  heat: {type: numeric, depends_on: mode, show: "{value} C",
         cases: {gentle: {ranges: [[150, 150, 5]]}, normal: {ranges: [[170, 180, 5]]}}}
"""
)


def test_a_walk_in_one_mode_leaves_the_goal_mode_to_be_walked() -> None:
    episode, reached = run(model_from(TRUTH), model_from(BELIEF), {"mode": "gentle", "heat": 160})
    assert reached, episode.failure
