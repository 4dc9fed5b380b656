"""A goal setting the loop gives up on costs that setting only: the rest of the goal is still
set, so what ends up set does not depend on whether the stuck setting was first or last in the
plan, and the run never claims success."""

from __future__ import annotations

import pytest

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.executed import AgentConfig, GiveUp, Stop
from apbot.agent.loop import ClosedLoop
from apbot.model.goal import parse_goal
from tests.helpers import model_from

# A fan heater: a heat level and a run-on time, each on its own key.
FAN = """
controls: [{id: heat, label: HEAT}, {id: time, label: TIME}]
variables:
  heat: {type: discrete, values: [low, mid, high], show: {low: H1, mid: H2, high: H3}}
  time: {type: numeric, unit: min, ranges: [[0, 30, 10]], initial: 0, show: "{value} MIN"}
actions: {press_heat: {control: heat}, press_time: {control: time}}
features:
  heat: [{actions: [press_heat], variable: heat, effect: next}]
  time: [{actions: [press_time], variable: time, effect: next}]
"""


def loop(goal: dict[str, object]) -> ClosedLoop:
    model = model_from(FAN)
    env = SimulatorEnvironment(model)
    context = TaskContext("unit", "test", "t", "", goal, model, actions=tuple(env.actions))
    return ClosedLoop(AgentConfig(), context, env)


def test_a_stuck_setting_is_set_aside_while_another_is_still_to_set() -> None:
    agent = loop({"heat": "high", "time": 20})
    agent.pending = ["stale"]  # type: ignore[list-item]
    assert agent.set_aside_for_the_rest(GiveUp("press_heat keeps failing", frozenset({"heat"})))
    inside, outside = agent.goal()
    assert inside == {"time": 20} and not outside  # planned without the stuck setting
    assert agent.pending == []  # the plan that included it is dropped


def test_nothing_else_to_set_or_no_goal_setting_stops_as_before() -> None:
    agent = loop({"heat": "high"})
    assert not agent.set_aside_for_the_rest(GiveUp("stuck", frozenset({"heat"})))
    agent = loop({"heat": "high", "time": 20})
    assert not agent.set_aside_for_the_rest(GiveUp("stuck", frozenset({"fan_speed"})))
    assert not agent.set_aside_for_the_rest(GiveUp("stuck", frozenset()))


def test_the_same_setting_stuck_twice_stops() -> None:
    agent = loop({"heat": "high", "time": 20})
    assert agent.set_aside_for_the_rest(GiveUp("stuck", frozenset({"heat"})))
    assert not agent.set_aside_for_the_rest(GiveUp("stuck again", frozenset({"heat"})))


def test_with_a_setting_set_aside_the_rest_is_set_but_never_claimed() -> None:
    agent = loop({"heat": "high", "time": 20})
    assert agent.set_aside_for_the_rest(GiveUp("press_heat keeps failing", frozenset({"heat"})))
    episode = agent.run()
    simulator = agent.session.env.simulator  # type: ignore[attr-defined]
    assert simulator.satisfies(parse_goal(simulator.model, {"time": 20}))
    assert not simulator.satisfies(parse_goal(simulator.model, {"heat": "high"}))
    assert not episode.claimed_success
    assert episode.failure.startswith("press_heat keeps failing")


def test_the_session_gives_up_on_the_named_settings_only() -> None:
    agent = loop({"heat": "high", "time": 20})
    for _ in range(3):
        agent.session.again("value", "heat", "heat keeps showing", ["heat"])
    with pytest.raises(GiveUp) as stuck:
        agent.session.again("value", "heat", "heat keeps showing", ["heat"])
    assert stuck.value.names == {"heat"}
    for _ in range(3):
        agent.session.again("procedure", "x", "x keeps failing")
    with pytest.raises(Stop) as plain:
        agent.session.again("procedure", "x", "x keeps failing")
    assert not isinstance(plain.value, GiveUp)
