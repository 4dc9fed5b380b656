"""The end check that cannot read a goal setting it looked at: before it gives up, it learns
how the display prints the setting from the texts its looks brought up (as it does after a
macro action's press), then reads and settles the value."""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from tests.helpers import model_from

STERILISER = """
controls: [{id: power, label: POWER}, {id: dry, label: DRY}, {id: time, label: TIME}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  dry: {type: discrete, values: ["off", "on"], label: DRY{lamp}}
  time: {type: time, ranges: [{ranges}], initial: "{initial}", wrap: true, {shown}}
actions:
  press_power: {control: power}
  press_dry: {control: dry}
  press_time: {control: time}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  dry: [{actions: [press_dry], variable: dry, effect: toggle}]
  set_time: [{actions: [press_time], variable: time, effect: next}]
guards:
  - {when: {power: "off"}, only: [press_power], display: ""}
display: {idle: "READY", indicators: [{lamps}]}
"""


def _steriliser(ranges: str, initial: str, shown: str, truth: bool) -> str:
    # the panel keeps "DRY on" lit beside whatever it shows; the belief knows only the screen
    # the key brings up, "DRY on"
    lamp = ', show: {"off": "", "on": "DRY on"}' if truth else ""
    return (
        STERILISER.replace("{ranges}", ranges)
        .replace("{initial}", initial)
        .replace("{shown}", shown)
        .replace("{lamp}", lamp)
        .replace("{lamps}", "dry" if truth else "")
    )


def test_a_setting_only_looked_at_is_read_from_the_looks_texts() -> None:
    # the panel prints the time as "c 9 min" and walks 5, 7, 9, 11 minutes
    truth = model_from(
        _steriliser(
            '["00:05:00", "00:11:00", 120]', "00:09:00", 'format: min, show: "c {value}"', True
        )
    )
    # the manual's reader took it for "TIME 05:00", from 5 to 9 minutes, starting at 5
    belief = model_from(
        _steriliser(
            '["00:05:00", "00:09:00", 120]', "00:05:00", "format: mm:ss, label: TIME", False
        )
    )
    env = SimulatorEnvironment(truth, "display")
    goal = {"dry": "on", "time": "00:05:00"}  # the time asked is the one believed already
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, goal)), episode.failure
    assert episode.claimed_success, episode.failure
