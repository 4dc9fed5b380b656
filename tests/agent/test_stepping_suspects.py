"""The finder walks ▲/▼ keys whose role in the belief cannot hold the goal's value.

A reader may give the panel's stepping keys to the wrong setting (▲/▼ read as a timer's where
they set a target temperature). A temperature the belief lacks is then looked for on those
keys too, named like it or not: levels are stepped there. A long press is not tried (it does
something else: a lock, a boost). Small panels written for these tests.
"""

from __future__ import annotations

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.model.goal import parse_goal
from tests.helpers import model_from

TRUTH = """
controls: [{id: power}, {id: up}, {id: down}]
variables:
  power: {type: discrete, values: ["off", "on"], initial: "on", show: {"off": "", "on": "{target}"}}
  target: {type: numeric, unit: "°C", ranges: [[40, 90, 1]], initial: 60}
actions:
  press_power: {control: power}
  press_up: {control: up}
  press_down: {control: down}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  target:
    - actions: [press_up, press_down]
      variable: target
      effect: {press_up: next, press_down: prev}
"""

BELIEF = """
controls: [{id: power}, {id: up}, {id: down}]
variables:
  power: {type: discrete, values: ["off", "on"], initial: "on", show: {"off": "", "on": ""}}
  timer: {type: time, ranges: [["00:01:00", "01:00:00", 60]], label: TIMER}
actions:
  press_power: {control: power}
  press_up: {control: up}
  press_down: {control: down}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  set_timer:
    - {actions: [press_up, press_down], variable: timer, effect: {press_up: next, press_down: prev}}
"""


def test_a_temperature_is_found_on_stepping_keys_read_as_a_timer() -> None:
    truth, belief = model_from(TRUTH), model_from(BELIEF)
    env = SimulatorEnvironment(truth, "display")
    goal = {"meat_temperature": "57 °C"}  # the parser's open entry: no belief setting takes it
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=env.actions)
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, {"target": 57}))
    assert episode.claimed_success, episode.failure
    assert any("found under press_up" in r for r in episode.repairs)
