"""A third-party simulator becomes an environment in a line, and the agent runs on it."""

from __future__ import annotations

import doctest
from pathlib import Path
from typing import Any

import pytest

from apbot.agent.environment import Environment, Feedback
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.agent.wrappers import FunctionEnvironment, ObjectEnvironment
from tests.helpers import model_from

DOCS = Path(__file__).resolve().parents[2] / "docs" / "environments.md"


class Locked(Exception):
    """What this third-party fan raises for a button that does nothing."""


class Fan:
    """A desk fan written without apbot in mind: its own names and spellings."""

    def __init__(self, speeds: tuple[str, ...] = ("Low", "Medium", "High")) -> None:
        self.speeds = speeds
        self.held: float | None = None
        self.reset()

    def reset(self) -> dict[str, Any]:
        self.on, self.speed, self.lock = False, 0, False
        return self.state()

    def press_power(self) -> dict[str, Any]:
        if self.lock:
            raise Locked("LOCKED")
        self.on = not self.on
        return self.state()

    def press_speed(self) -> tuple[str, dict[str, Any]]:
        if not self.on:
            raise Locked("fan is off")
        self.speed = (self.speed + 1) % len(self.speeds)
        return f"SPEED {self.speed + 1}", self.state()

    def hold_lock(self, seconds: float = 3) -> dict[str, Any]:
        self.held = seconds
        if seconds >= 3:
            self.lock = not self.lock
        return {"lock": self.lock}

    def beep(self) -> str:
        return "BEEP"

    def broken(self) -> list[str]:
        return ["not", "feedback"]

    def state(self) -> dict[str, Any]:
        return {"Fan": "ON", "Spd": self.speeds[self.speed]} if self.on else {"Fan": "OFF"}


BELIEF = """
controls: [{id: power, label: POWER}, {id: speed, label: SPEED}]
variables:
  power: {type: discrete, values: ["off", "on"], label: FAN}
  speed: {type: discrete, values: [%s]}
actions: {press_power: {control: power}, press_speed: {control: speed}}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_speed: [{actions: [press_speed], variable: speed, effect: next}]
guards: [{when: {power: "off"}, only: [press_power]}]
"""


def wrapped(**options: Any) -> ObjectEnvironment:
    options.setdefault("refusals", (Locked,))
    return ObjectEnvironment(Fan(), **options)


def test_public_methods_are_the_actions_and_the_wrapper_is_an_environment() -> None:
    env = wrapped()
    assert env.actions == ("press_power", "press_speed", "hold_lock", "beep", "broken", "state")
    assert isinstance(env, Environment)
    assert wrapped(actions=["press_power", "press_speed"]).actions == ("press_power", "press_speed")


def test_every_kind_of_result_becomes_feedback() -> None:
    env = wrapped()
    assert env.reset() == Feedback("Fan: OFF", {"Fan": "OFF"})
    assert env.step("press_power") == Feedback("Fan: ON, Spd: Low", {"Fan": "ON", "Spd": "Low"})
    assert env.step("press_speed") == Feedback("SPEED 2", {"Fan": "ON", "Spd": "Medium"})
    assert env.step("beep") == Feedback("BEEP", {})
    lcd = wrapped(text=lambda fan: f"LCD {fan.speed}")
    assert lcd.step("press_power").text == "LCD 0"


def test_a_listed_exception_is_a_refusal_and_others_propagate() -> None:
    env = wrapped()
    env.reset()
    refused = env.step("press_speed")
    assert (refused.accepted, refused.reason, refused.values) == (False, "fan is off", {})
    with pytest.raises(Locked):
        wrapped(refusals=()).step("press_speed")


def test_a_hold_gets_its_seconds_when_the_method_takes_them() -> None:
    env = wrapped()
    assert env.step("hold_lock", seconds=1).values == {"lock": False}
    assert env.obj.held == 1
    assert env.step("hold_lock", seconds=3).values == {"lock": True}
    assert not env.step("press_power").accepted


def test_bad_names_and_results_are_explained() -> None:
    env = wrapped()
    with pytest.raises(KeyError, match=r"'press_speeed'.*did you mean 'press_speed'"):
        env.step("press_speeed")
    with pytest.raises(TypeError, match=r"broken returned a list"):
        env.step("broken")
    with pytest.raises(ValueError, match=r"no method 'press_pwr'.*'press_power'"):
        ObjectEnvironment(Fan(), actions=["press_pwr"])
    with pytest.raises(TypeError, match=r"no method 'restart'.*reset=None"):
        ObjectEnvironment(Fan(), reset="restart")
    assert ObjectEnvironment(Fan(), reset=None).reset() == Feedback()


def test_a_step_function_is_an_environment_too() -> None:
    fan = Fan()
    calls: list[tuple[str, float | None]] = []

    def step(action: str, seconds: float | None = None) -> Any:
        calls.append((action, seconds))
        return getattr(fan, action)()

    env = FunctionEnvironment(step, ["press_power", "press_speed"], fan.reset, (Locked,))
    assert env.reset().values == {"Fan": "OFF"}
    assert not env.step("press_speed").accepted
    assert env.step("press_power", seconds=2).values == {"Fan": "ON", "Spd": "Low"}
    assert calls[-1] == ("press_power", 2)
    with pytest.raises(KeyError, match="press_lock"):
        env.step("press_lock")


@pytest.mark.parametrize("speeds", ["low, medium, high", "low, high"])
def test_the_agent_operates_a_wrapped_fan_from_its_own_belief(speeds: str) -> None:
    env = wrapped(actions=["press_power", "press_speed"])
    belief = model_from(BELIEF % speeds)
    context = TaskContext(
        "fan",
        "fan",
        "t01",
        "Run the fan at high speed.",
        {"power": "on", "speed": "high"},
        belief,
        actions=tuple(env.actions),
    )
    episode = get_method("apbot").run(context, env)
    assert episode.claimed_success
    assert env.obj.on and env.obj.speeds[env.obj.speed] == "High"
    assert bool(episode.repairs) == (speeds == "low, high")  # the wrong belief was repaired


def test_the_documented_examples_run() -> None:
    result = doctest.testfile(
        str(DOCS), module_relative=False, verbose=False, optionflags=doctest.ELLIPSIS
    )
    assert result.attempted > 10 and result.failed == 0
