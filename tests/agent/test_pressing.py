"""The press primitive (apbot.agent.pressing): what a press tells the belief beyond its reading."""

from __future__ import annotations

from apbot.agent.budget import Budget
from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.session import AgentConfig, Session
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from, run_checked

KETTLE = """
controls: [{id: power}, {id: plus}]
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "%(on)s"}}
  temp: {type: numeric, unit: "°C", ranges: [[40, 100, 5]], initial: 45, wrap: true,
        label: TEMP}
actions:
  press_power: {control: power}
  press_plus: {control: plus}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_temp: [{actions: [press_plus], variable: temp, effect: next}]
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], hide: true}
display:
  idle: "%(idle)s"
"""


def kettle(idle: str, on: str = "") -> ApplianceModel:
    return model_from(KETTLE % {"idle": idle, "on": on})


def session(truth: ApplianceModel, belief: ApplianceModel) -> Session:
    env = SimulatorEnvironment(truth, "display")
    context = TaskContext("kettle", "test", "t", "", {}, belief, actions=tuple(env.actions))
    started = Session(AgentConfig(), context, env, Budget())
    started.start()
    return started


def test_a_dark_panel_the_switch_lit_says_the_switch_is_on_whatever_it_shows() -> None:
    # the kettle greets with "READY 45°C"; the belief can print no such screen
    s = session(kettle("{temp}°C", on="READY {temp}°C  HOT"), kettle(""))
    done = s.press(s.planned("press_power"))
    assert done.seen is not None and done.seen.unknown
    assert not done.surprises and s.belief.value("power") == "on"


def test_a_panel_still_dark_says_nothing_of_the_kind() -> None:
    s = session(kettle(""), kettle(""))
    done = s.press(s.planned("press_power"))
    assert s.belief.value("power") == "on" and "power" not in done.surprises
    assert "power" not in s.evidence  # a blank display confirms nothing


def test_the_switch_is_not_pressed_off_again_when_the_panel_greets_unreadably() -> None:
    truth, belief = kettle("{temp}°C", on="READY {temp}°C"), kettle("")
    episode, reached = run_checked(truth, belief, {"power": "on"})
    assert reached
    assert [e.action for e in episode.trace if e.kind == "action"] == ["press_power"]
