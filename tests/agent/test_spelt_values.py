"""A walk that shows a worded setting's values spelt out (the manual's "lo" is the panel's
"low"): the goal the agent read in the belief's words follows the new names."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from tests.helpers import model_from

FAN = """
controls: [{id: flow, label: AIRFLOW}]
variables:
  airflow: {type: discrete, values: [{values}], label: AIRFLOW}
actions:
  press_flow: {control: flow}
features:
  set_airflow:
    - {actions: [press_flow], variable: airflow, effect: next}
display: {idle: "READY"}
"""


def test_a_goal_value_the_panel_spells_out_is_still_reached() -> None:
    truth = model_from(FAN.replace("{values}", "off, low, high"))
    belief = model_from(FAN.replace("{values}", "off, lo, hi"))
    env = SimulatorEnvironment(truth, "display")
    goal = {"airflow": "hi"}  # in the belief's words, as the goal parser read it
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, {"airflow": "high"}))
    assert episode.claimed_success, episode.failure
