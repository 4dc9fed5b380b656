"""ApBot with the true model solves tasks on models that use the format's newer constructs
(hold-to-scroll, conditional effects, one-position guards, settings remembered per
programme, values declared unreachable),
with display feedback only, in the optimal number of presses and without repairs; a goal on
a value declared unreachable ends in a declared failure, not in wandering."""

from __future__ import annotations

from typing import Any

import pytest

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from apbot.plan.plan import plan
from tests.helpers import model_from
from tests.sim.test_behaviours import PLUS30, SCROLL, WASHER

DIAL = """
controls: [{id: dial, kind: dial, label: MODE}, {id: plus, label: "+"}]
variables:
  mode: {type: discrete, values: ["off", toast, timer, auto], wrap: false, unreachable: [auto]}
  minutes: {type: numeric, unit: min, ranges: [[0, 30, 5]]}
actions:
  turn_cw: {control: dial, skill: turn_cw}
  turn_ccw: {control: dial, skill: turn_ccw}
  press_plus: {control: plus}
features:
  mode:
    - actions: [turn_cw, turn_ccw]
      variable: mode
      effect: {turn_cw: {when: {mode: timer}, then: none, otherwise: next}, turn_ccw: prev}
  minutes: [{actions: [press_plus], variable: minutes, effect: next}]
guards:
  - {name: keys in TIMER only, when: {mode: {other_than: timer}}, only: [turn_cw, turn_ccw],
     display: "TURN TO TIMER"}
"""

CASES = [
    (SCROLL.replace("WRAP", "false"), {"level": "13"}),
    (SCROLL.replace("WRAP", "true"), {"level": "2"}),
    (PLUS30, {"cook_time": "00:01:30", "running": "on"}),
    (PLUS30, {"cook_time": "00:02:00", "running": "on"}),
    (DIAL, {"minutes": "15 min", "mode": "timer"}),
    (DIAL, {"minutes": "10", "mode": "toast"}),
    (WASHER.replace("REMEMBER", "true"), {"programme": "synthetics", "temperature": "40"}),
    (WASHER.replace("REMEMBER", "true"), {"temperature": "60", "power": "on"}),
]


def run(text: str, goal: dict[str, Any]) -> tuple[Any, bool, int]:
    model = model_from(text)
    env = SimulatorEnvironment(model, feedback="display")
    context = TaskContext("unit", "test", "t01", "do it", goal, model, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    return episode, env.simulator.satisfies(parse_goal(model, goal)), env.steps


@pytest.mark.parametrize(("text", "goal"), CASES)
def test_apbot_with_the_true_model_reaches_the_goal_optimally(
    text: str, goal: dict[str, Any]
) -> None:
    episode, reached, steps = run(text, goal)
    assert reached and episode.claimed_success, episode.failure
    assert not episode.repairs
    assert steps == len(plan(model_from(text), None, goal))


def test_a_goal_on_a_value_declared_unreachable_fails_cleanly() -> None:
    episode, reached, _ = run(DIAL, {"mode": "auto"})
    assert not reached and not episode.claimed_success
    assert "declares it unreachable" in episode.failure
