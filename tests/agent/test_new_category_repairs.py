"""Regression tests for the closed loop on beliefs of the new categories (issue 12): each
runs the agent on a small model with a fault met on a coffee machine, a dishwasher, an air
conditioner…, against the true simulator, and judges the outcome on the truth."""

from __future__ import annotations

from typing import Any

import pytest

from apbot.agent.environment import FeedbackMode, SimulatorEnvironment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.reader import DisplayReader
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from

MODES: tuple[FeedbackMode, ...] = ("display", "values")


def run(
    truth: ApplianceModel, belief: ApplianceModel, goal: dict[str, Any], feedback: FeedbackMode
) -> tuple[Episode, bool]:
    env = SimulatorEnvironment(truth, feedback)
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    reached = env.simulator.satisfies(parse_goal(truth, goal))
    assert not (episode.claimed_success and not reached), "a false claim of success"
    return episode, reached


# --- a lamp the belief does not know, read as a bare number ------------------------------------

COFFEE = """
controls: [{id: small, label: "1-4 CUP"}, {id: warm, label: WARM}, {id: onoff, label: "ON/OFF"}]
variables:
  small_batch: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "1-4"}}
  keep_warm: {type: numeric, unit: h, ranges: [[0.5, 1, 0.5], [1, 4, 1]], initial: 2,
              wrap: true, show: "{value}"}
  brewing: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "ON"}}
actions: {press_small: {control: small}, press_warm: {control: warm}, press_onoff: {control: onoff}}
features:
  small_batch: [{actions: [press_small], variable: small_batch, effect: toggle}]
  keep_warm: [{actions: [press_warm], variable: keep_warm, effect: next}]
  on_off: [{actions: [press_onoff], variable: brewing, effect: toggle}]
display: {idle: "12:00", indicators: [small_batch, brewing]}
"""

# the reader missed the 1-4 CUP setting and filed its key as the entry of the WARM procedure
COFFEE_MERGED = """
controls: [{id: small, label: "1-4 CUP"}, {id: warm, label: WARM}, {id: onoff, label: "ON/OFF"}]
variables:
  keep_warm: {type: numeric, unit: h, ranges: [[0.5, 1, 0.5], [1, 4, 1]], initial: 2,
              wrap: true, show: "{value}"}
  brewing: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "ON"}}
actions: {press_small: {control: small}, press_warm: {control: warm}, press_onoff: {control: onoff}}
features:
  small_batch:
    - {actions: [press_small]}
    - {actions: [press_warm], variable: keep_warm, effect: next}
  on_off: [{actions: [press_onoff], variable: brewing, effect: toggle}]
display: {idle: "12:00", indicators: [brewing]}
"""


def test_a_bare_number_inside_an_unknown_lamp_is_no_reading_of_it() -> None:
    reader = DisplayReader(model_from(COFFEE_MERGED))
    assert reader.read("1-4").unknown  # not keep_warm 1 h: "1" is part of a longer word
    (within,) = [h for h in reader.read("1 h  DOOR").hypotheses if h.partial]
    assert within.values == {"keep_warm": 1}


@pytest.mark.parametrize("feedback", MODES)
def test_an_unknown_lamp_never_confirms_a_goal_value(feedback: FeedbackMode) -> None:
    episode, reached = run(
        model_from(COFFEE),
        model_from(COFFEE_MERGED),
        {"brewing": "on", "keep_warm": "1 h"},
        feedback,
    )
    assert reached and episode.claimed_success, episode.failure
