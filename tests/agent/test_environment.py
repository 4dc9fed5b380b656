"""What a simulated appliance reveals to an agent, in each feedback mode."""

from __future__ import annotations

import pytest

from apbot.agent.environment import SimulatorEnvironment
from tests.helpers import model_from

PANEL = """
controls: [{id: power}, {id: mode}, {id: lock}, {id: start}, {id: secret}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  mode: {type: discrete, values: [a, b, c]}
  child_lock: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "LOCK"}}
  service: {type: discrete, values: [x, y], visible: false}
actions:
  press_power: {control: power}
  press_mode: {control: mode}
  hold_lock: {control: lock, skill: hold, seconds: 3}
  press_start: {control: start}
  press_secret: {control: secret}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  mode: [{actions: [press_mode], variable: mode, effect: next}]
  lock: [{actions: [hold_lock], variable: child_lock, effect: toggle}]
  service: [{actions: [press_secret], variable: service, effect: next}]
  start: [{actions: [press_start], set: {mode: a}}, {actions: [press_mode]}]
guards:
  - {name: switched off, when: {power: "off"}, only: [press_power], display: "", hide: true}
  - {name: child lock, when: {child_lock: "on"}, only: [hold_lock], display: "LOCKED"}
display:
  indicators: [child_lock, service]
%s
"""


def env_for(feedback: str, ignored: str = "") -> SimulatorEnvironment:
    model = model_from(PANEL % (f"  ignored: {ignored}" if ignored else ""))
    env = SimulatorEnvironment(model, feedback)  # type: ignore[arg-type]
    env.reset()
    return env


def test_display_mode_gives_text_only_and_lamps_after_the_main_display() -> None:
    env = env_for("display")
    env.step("press_power")
    env.step("hold_lock")
    shown = env.step("press_mode")  # refused by the lock: the message and the lamp
    assert (shown.text, shown.values, shown.accepted) == ("LOCKED  LOCK", {}, False)


def test_a_key_that_does_nothing_is_silent_unless_the_model_says_it_beeps() -> None:
    silent = env_for("display")
    silent.step("press_power")
    before = silent.step("press_mode").text
    ignored = silent.step("hold_lock", seconds=1)  # too short: nothing happens
    assert ignored.accepted and ignored.text == before
    beeping = env_for("display", ignored="beep")
    beeping.step("press_power")
    assert not beeping.step("hold_lock", seconds=1).accepted


def test_a_dark_panel_ignores_keys_without_a_sign() -> None:
    env = env_for("display")
    shown = env.step("press_mode")
    assert shown.accepted and shown.text == ""


def test_values_mode_reports_every_refusal_and_the_shown_values() -> None:
    env = env_for("values")
    refused = env.step("press_mode")
    assert not refused.accepted and refused.reason == "refused"  # never the true reason
    shown = env.step("press_power")
    assert shown.values == {"power": "on", "child_lock": "off"}


@pytest.mark.parametrize("feedback", ["display", "values"])
def test_an_invisible_variable_never_appears_in_any_feedback(feedback: str) -> None:
    env = env_for(feedback)
    env.step("press_power")
    for _ in range(3):
        shown = env.step("press_secret")
        assert "service" not in shown.values and shown.text == ""
