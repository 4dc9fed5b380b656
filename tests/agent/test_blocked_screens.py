"""Screens that say a setting cannot be changed now: the manual names what blocks it
(:mod:`apbot.agent.blocked`), and a refusal suspects a lock's release left off
(:meth:`apbot.agent.guards.GuardLearner._suspects`)."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from tests.helpers import model_from

SPRINKLER = """
controls: [{id: mode, label: MODE}, {id: mins, label: MINS}, {id: zone, label: ZONE}]
variables:
  mode: {type: discrete, values: [auto, man], initial: auto, label: MODE}
  zone: {type: discrete, values: [front, back], initial: front, label: ZONE}
  minutes: {type: numeric, ranges: [[1, 9, 1]], initial: 3, wrap: true, label: MIN}
actions:
  press_mode: {control: mode}
  press_mins: {control: mins}
  press_zone: {control: zone}
features:
  set_mode: [{actions: [press_mode], variable: mode, effect: next}]
  set_zone: [{actions: [press_zone], variable: zone, effect: next}]
  set_minutes: [{actions: [press_mins], variable: minutes, effect: next}]
{guards}
display: {idle: "{mode}", indicators: [zone]}
"""

GUARD = """guards:
  - {name: planned, when: {mode: auto}, only: [press_mode, press_zone], display: "MIN --"}
"""

MANUAL = """
Watering time
Press MINS to add a minute of watering. The watering time can only be chosen by hand.

Display messages
  MIN --      the watering time cannot be set: the timer runs in AUTO
  ZONE B      the back lawn is watered
"""


def _run(model: str, truth_guard: str, manual: str, goal: dict[str, object]) -> tuple[bool, bool]:
    truth = model_from(model.replace("{guards}", truth_guard))
    belief = model_from(model.replace("{guards}", ""))
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext(
        "unit", "test", "t", "", goal, belief, manual=manual, actions=tuple(env.actions)
    )
    episode = get_method("apbot").run(context, env)
    return env.simulator.satisfies(parse_goal(truth, goal)), episode.claimed_success


def test_a_setting_the_manual_says_is_blocked_in_a_mode_is_set_after_leaving_it() -> None:
    assert _run(SPRINKLER, GUARD, MANUAL, {"minutes": 6}) == (True, True)


def test_without_the_manuals_line_the_block_stays_unexplained() -> None:
    manual = MANUAL.replace("MIN --", "(no message)")
    done, claimed = _run(SPRINKLER, GUARD, manual, {"minutes": 6})
    assert not done and not claimed


DISPENSER = """
controls: [{id: room, label: ROOM}, {id: hot, label: HOT}, {id: release, label: RELEASE}]
variables:
  water: {type: discrete, values: [room, hot], initial: room, label: WATER}
  hot_unlock: {type: discrete, values: ["off", "on"], initial: "off", label: OPEN}
actions:
  press_room: {control: room}
  press_hot: {control: hot}
  hold_release: {control: release, skill: hold, seconds: 2}
features:
  room: [{actions: [press_room], variable: water, effect: {to: room}}]
  hot: [{actions: [press_hot], variable: water, effect: {to: hot}}]
  release: [{actions: [hold_release], variable: hot_unlock, effect: toggle}]
{guards}
display: {idle: "{water}", indicators: [hot_unlock]}
"""

SAFETY = """guards:
  - {name: safety, when: {hot_unlock: "off"}, only: [press_room, hold_release], display: "SAFE"}
"""


def test_a_refused_key_is_freed_by_switching_a_release_that_is_off() -> None:
    assert _run(DISPENSER, SAFETY, "", {"water": "hot"}) == (True, True)
