"""The closed loop recovers from a wrong belief; the open loop does not."""

from __future__ import annotations

import pytest

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import GoalError, parse_goal
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from

HEATER = """
controls:
  - {id: power, label: POWER}
  - {id: mode, label: MODE}
  - {id: timer, label: TIMER}
  - {id: up, label: "+"}
  - {id: down, label: "-"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  mode: {type: discrete, values: [%(modes)s], wrap: %(mode_wrap)s}
  temperature: {type: numeric, unit: "°C", ranges: [%(temp_ranges)s], initial: 20}
  timer: {type: numeric, unit: h, ranges: [[0, 12, 1]], initial: 0}
actions:
  press_power: {control: power}
  press_mode: {control: mode}
  press_timer: {control: timer}
  press_up: {control: up}
  press_down: {control: down}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_mode: [{actions: [press_mode], variable: mode, effect: next}]
  set_temperature:
    - {actions: [press_up, press_down], variable: temperature,
       effect: {press_up: %(up)s, press_down: %(down)s}}
  set_timer:
%(timer_steps)s
guards:
  - {when: {power: "off"}, only: [press_power], display: "", hide: true}
"""

TIMER_STEPS = """    - {actions: [press_timer]}
    - {actions: [press_up, press_down], variable: timer, effect: {press_up: next, press_down: prev}}
"""

TRUTH = dict(
    modes="comfort, eco, frost, boost",
    mode_wrap="true",
    temp_ranges="[10, 30, 1]",
    up="next",
    down="prev",
    timer_steps=TIMER_STEPS,
)


def heater(**changes: str) -> ApplianceModel:
    return model_from(HEATER % {**TRUTH, **changes})


def run(
    method: str, belief: ApplianceModel, goal: dict[str, str], truth: ApplianceModel | None = None
) -> tuple[Episode, bool, int]:
    truth = truth or heater()
    env = SimulatorEnvironment(truth)
    context = TaskContext(
        "heater", "test", "t01", "an instruction", goal, belief, actions=tuple(env.actions)
    )
    episode = get_method(method).run(context, env)
    try:
        reached = env.simulator.satisfies(parse_goal(truth, goal))
    except GoalError:  # the goal is not a state of the appliance at all
        reached = False
    return episode, reached, env.steps


def test_with_the_true_model_apbot_takes_the_optimal_path_without_repairs() -> None:
    episode, reached, steps = run("apbot", heater(), {"temperature": "24", "mode": "frost"})
    assert reached and episode.claimed_success and not episode.repairs
    assert steps == 1 + 2 + 4  # power, mode twice, up four times
    assert episode.reasoning_steps == 3
    assert not any(e.exploring for e in episode.trace)


def test_a_wrong_step_size_is_explored_and_repaired() -> None:
    belief = heater(temp_ranges="[10, 30, 2]")
    episode, reached, _ = run("apbot", belief, {"temperature": "24"})
    assert reached and episode.claimed_success
    assert any("temperature" in r for r in episode.repairs)
    assert any(e.exploring for e in episode.trace)
    _, open_reached, _ = run("apbot-open-loop", belief, {"temperature": "24"})
    assert not open_reached


def test_a_goal_value_missing_from_the_belief_is_found_by_exploring() -> None:
    belief = heater(modes="comfort, eco, boost")
    episode, reached, _ = run("apbot", belief, {"mode": "frost"})
    assert reached, episode.trace
    assert any("frost" in r for r in episode.repairs)
    open_episode, open_reached, _ = run("apbot-open-loop", belief, {"mode": "frost"})
    assert not open_reached and "frost" in open_episode.failure


def test_wrong_value_order_and_wrap_are_learnt() -> None:
    belief = heater(modes="comfort, frost, eco, boost", mode_wrap="false")
    episode, reached, _ = run("apbot", belief, {"mode": "eco"})
    assert reached and episode.repairs


def test_keys_that_move_the_other_way_are_learnt() -> None:
    belief = heater(up="prev", down="next")
    episode, reached, _ = run("apbot", belief, {"temperature": "25", "timer": "3 h"})
    assert reached and any("other way" in r for r in episode.repairs)


def test_a_missing_entry_step_is_found_among_unused_actions() -> None:
    # the checker rejects this belief (TIMER is used nowhere, set_timer can never start): a
    # reader's first draft; the agent must still find its way
    belief = model_from(
        HEATER
        % {
            **TRUTH,
            "timer_steps": "    - {actions: [press_up, press_down], "
            "variable: timer, effect: {press_up: next, press_down: prev}}\n",
        },
        check=False,
    )
    episode, reached, _ = run("apbot", belief, {"timer": "4 h"})
    assert reached, [e.to_dict() for e in episode.trace]
    assert any("press_timer" in r for r in episode.repairs)


def test_an_impossible_goal_ends_in_a_declared_failure() -> None:
    episode, reached, _ = run("apbot", heater(), {"temperature": "45"})
    assert not reached and not episode.claimed_success
    assert "temperature" in episode.failure


def test_the_run_stops_at_the_reasoning_step_limit() -> None:
    wide = heater(temp_ranges="[10, 60, 1]")
    episode, reached, _ = run("apbot-no-button-policy", wide, {"temperature": "50"}, wide)
    assert episode.reasoning_steps == 25 and not reached
    assert "25 reasoning steps" in episode.failure


def test_a_setting_with_one_believed_value_is_inspected_not_looped_on() -> None:
    """The belief knows one temperature for the eco programme; the appliance has two."""
    from importlib.resources import files

    from apbot.examples import load_example
    from apbot.model.load import loads_model

    text = (files("apbot") / "data/examples/washing_machine.yaml").read_text()
    truth = loads_model(
        text.replace(
            'eco 40-60: {values: ["40"], initial: "40"}',
            'eco 40-60: {values: ["40", "60"], initial: "40"}',
        )
    )
    assert truth != load_example("washing_machine")
    goal = {"programme": "eco 40-60", "temperature": "60"}
    episode, reached, _ = run("apbot", load_example("washing_machine"), goal, truth)
    assert reached, [e.to_dict() for e in episode.trace if not e.exploring]
    assert any("temperature" in r for r in episode.repairs)


def test_a_goal_value_of_the_wrong_kind_stops_before_any_press() -> None:
    episode, reached, steps = run("apbot", heater(), {"timer": "banana"})
    assert not reached and steps == 0 and "timer" in episode.failure


def test_the_loop_searches_each_question_once_per_belief(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    import apbot.agent.loop as loop_module
    import apbot.agent.planning as planning_module
    from apbot.agent.session import AgentConfig
    from apbot.plan.plan import Unreachable

    asked: list[dict[str, str]] = []
    searched = planning_module.plan

    def counting(compiled, state, target, *args):  # type: ignore[no-untyped-def]
        asked.append(dict(target))
        return searched(compiled, state, target, *args)

    monkeypatch.setattr(planning_module, "plan", counting)
    # no key raises the temperature (a belief the checker would refuse; the loop may hold one)
    belief = model_from(HEATER % {**TRUTH, "up": "prev"}, check=False)
    env = SimulatorEnvironment(heater())
    context = TaskContext("heater", "test", "t", "", {}, belief, actions=tuple(env.actions))
    loop = loop_module.ClosedLoop(AgentConfig(), context, env)
    first = loop.plans.plan({"power": "on", "timer": "3"})
    assert loop.plans.plan({"timer": "3", "power": "on"}) is first and len(asked) == 1
    for _ in range(2):  # a failed search is remembered too
        with pytest.raises(Unreachable):
            loop.plans.plan({"power": "on", "temperature": "25"})
    assert len(asked) == 2
    loop.session.belief.replace(heater())  # a repaired belief asks again
    loop.plans.plan({"power": "on", "timer": "3"})
    assert len(asked) == 3
