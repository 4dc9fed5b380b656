"""A walk back from the end a numeric setting's walk found stops at the goal's value: the step
and one end are known by then, and what lies beyond the goal is not asked for."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from tests.helpers import model_from

GRILL = """
controls: [{id: up, label: UP}, {id: down, label: DOWN}]
variables:
  heat: {type: numeric, unit: "°C", ranges: [[{low}, 250, {step}]], initial: 200, label: HEAT}
actions:
  press_up: {control: up}
  press_down: {control: down}
features:
  set_heat: [{actions: [press_up, press_down], variable: heat,
              effect: {press_up: next, press_down: prev}}]
display: {idle: "{heat}"}
"""


def test_the_walk_back_stops_at_the_goal_value() -> None:
    truth = model_from(GRILL.replace("{low}", "100").replace("{step}", "5"))
    belief = model_from(GRILL.replace("{low}", "100").replace("{step}", "10"))
    env = SimulatorEnvironment(truth, "display")
    goal = {"heat": 190}  # a value the belief has (every 10°)
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, goal)), episode.failure
    assert episode.claimed_success, episode.failure
    walks = [e.text for e in episode.trace if e.kind == "explore"]
    # down to the bottom (100), then back up to 190 only: never on to the top (250) and back
    assert walks and walks[0].endswith("under press_up: " + _summary(range(100, 195, 5))), walks
    assert episode.execution_steps < 50, episode.execution_steps


def _summary(values: range) -> str:
    """How the explore log lists a walk's values (the first ten, then their count)."""
    shown = ", ".join(str(v) for v in list(values)[:10])
    return f"{shown}, … ({len(values)})"
