"""A goal value a walk did not show, in a setting whose range the belief read for one mode only:
the closed loop sets the rest of the goal (the mode) first and walks the setting again there,
instead of walking it again where it already failed."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

# A steamer: the portion's range depends on the basket chosen (small 1 … 4, large 3 … 8); the
# reader missed the dependency and read the small basket's range for every basket.
STEAMER = """
controls: [{id: basket, label: BASKET}, {id: up, label: "+"}, {id: down, label: "-"},
           {id: go, label: GO}]
variables:
  basket: {type: discrete, values: [small, large], show: {small: SMALL, large: LARGE}}
  portion: {type: numeric, depends_on: basket, show: "{value} P",
            cases: {small: {ranges: [[1, 4, 1]], initial: 2},
                    large: {ranges: [[3, 8, 1]], initial: 5}}}
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "RUN"}}
actions: {press_basket: {control: basket}, press_up: {control: up},
          press_down: {control: down}, press_go: {control: go}}
features:
  basket: [{actions: [press_basket], variable: basket, effect: next}]
  portion:
    - {actions: [press_up, press_down], variable: portion,
       effect: {press_up: next, press_down: prev}}
  start: [{actions: [press_go], variable: running, effect: toggle}]
guards: [{when: {running: "on"}, only: [press_go]}]
display: {indicators: [running]}
"""

BELIEF = """
controls: [{id: basket, label: BASKET}, {id: up, label: "+"}, {id: down, label: "-"},
           {id: go, label: GO}]
variables:
  basket: {type: discrete, values: [small, large], show: {small: SMALL, large: LARGE}}
  portion: {type: numeric, ranges: [[1, 4, 1]], initial: 2, show: "{value} P"}
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "RUN"}}
actions: {press_basket: {control: basket}, press_up: {control: up},
          press_down: {control: down}, press_go: {control: go}}
features:
  basket: [{actions: [press_basket], variable: basket, effect: next}]
  portion:
    - {actions: [press_up, press_down], variable: portion,
       effect: {press_up: next, press_down: prev}}
  start: [{actions: [press_go], variable: running, effect: toggle}]
guards: [{when: {running: "on"}, only: [press_go]}]
display: {indicators: [running]}
"""


def test_a_value_missing_from_a_walk_is_looked_for_again_once_the_mode_is_set() -> None:
    goal = {"basket": "large", "portion": 7, "running": "on"}
    episode, reached = run(model_from(STEAMER), model_from(BELIEF), goal)
    assert reached, episode.failure
