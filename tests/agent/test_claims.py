"""The claim of success rests on what the display confirmed of what was asked: a request read
as no setting at all confirms nothing, so it is no success whatever the appliance shows."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from tests.helpers import model_from

LAMP = """
controls: [{id: mode, label: MODE}]
variables:
  mode: {type: discrete, values: [low, high], label: MODE}
actions:
  press_mode: {control: mode}
features:
  set_mode: [{actions: [press_mode], variable: mode, effect: next}]
display:
  idle: "{mode}"
"""


def test_a_request_read_as_nothing_is_not_claimed() -> None:
    # the user asked for something the goal reader could not place ("the cosy setting"): the
    # goal handed to the agent is empty, which the appliance trivially "holds"
    model = model_from(LAMP)
    env = SimulatorEnvironment(model, "display")
    context = TaskContext(
        "lamp", "test", "t", "the cosy one", {}, model, actions=tuple(env.actions)
    )
    episode = get_method("apbot").run(context, env)
    assert not episode.claimed_success
    assert "nothing" in episode.failure
    assert episode.execution_steps == 0


def test_a_request_read_as_a_setting_is_still_claimed_when_shown() -> None:
    model = model_from(LAMP)
    env = SimulatorEnvironment(model, "display")
    goal = {"mode": "high"}
    context = TaskContext("lamp", "test", "t", "high", goal, model, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    assert episode.claimed_success, episode.failure


TOASTER = """
controls: [{id: mode, label: MODE}, {id: shade, label: SHADE}]
variables:
  mode: {type: discrete, values: [toast, bagel], show: {toast: "TOAST", bagel: "BAGEL"}}
  shade: {type: discrete, values: [light, dark], label: SHADE}
actions:
  press_mode: {control: mode}
  press_shade: {control: shade}
features:
  set_mode: [{actions: [press_mode], variable: mode, effect: next}]
  set_shade: [{actions: [press_shade], variable: shade, effect: next, set: {mode: toast}}]
display:
  idle: "{shade}"
  indicators: [mode]
"""


def test_a_goal_setting_the_display_prints_at_another_value_is_not_claimed() -> None:
    # the reader missed that choosing the shade resets the mode, and that the mode's lamp
    # stays lit on the shade's screen: after SHADE the display prints the toast mode's word,
    # which the claim must not overlook
    truth = model_from(TOASTER)
    belief = model_from(
        TOASTER.replace(", set: {mode: toast}", "").replace("  indicators: [mode]\n", "")
    )
    env = SimulatorEnvironment(truth, "display")
    goal = {"shade": "dark", "mode": "bagel"}
    context = TaskContext(
        "toaster", "test", "t", "dark bagel", goal, belief, actions=tuple(env.actions)
    )
    episode = get_method("apbot").run(context, env)
    assert episode.claimed_success
    assert env.simulator.assignment()["mode"] == "bagel"
    assert any("prints mode=toast" in e.text for e in episode.trace if e.kind == "repair")


def test_a_number_the_goal_does_not_hold_is_not_claimed() -> None:
    # "high, for 3 hours": the lamp has no timer the reader found, so the goal holds only the
    # mode; the robot looks for the hours on the panel (agent/said_entries.py), sets the mode
    # and must say the hours were not found
    model = model_from(LAMP)
    env = SimulatorEnvironment(model, "display")
    goal = {"mode": "high"}
    context = TaskContext(
        "lamp", "test", "t", "high, for 3 hours", goal, model, actions=tuple(env.actions)
    )
    episode = get_method("apbot").run(context, env)
    assert not episode.claimed_success
    assert env.simulator.assignment()["mode"] == "high"
    assert "not found on the panel: time='3 h'" in episode.failure


def test_a_goal_handed_over_is_claimed_whatever_the_sentence_says() -> None:
    # a benchmark's stored goal (goal_read=False) answers for itself: the sentence's "3 hours"
    # is not a part the goal reader left, so reaching the goal is claimed
    model = model_from(LAMP)
    env = SimulatorEnvironment(model, "display")
    context = TaskContext(
        "lamp",
        "test",
        "t",
        "high, for 3 hours",
        {"mode": "high"},
        model,
        actions=tuple(env.actions),
        goal_read=False,
    )
    episode = get_method("apbot").run(context, env)
    assert episode.claimed_success
