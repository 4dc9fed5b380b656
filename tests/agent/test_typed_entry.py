"""Keypads that print an entry while it is typed, where the belief (read from a manual that
did not say so) expects the value after every digit. The digits on their way are no wrong
value whichever way the keypad fills its entry: shifted in from the right (a delay typed
2, 3, 0 shows ``00:02``, ``00:23``, ``02:30``), laid in from the left (a volume typed 2, 5, 0
shows ``2--``, ``25-``, ``250``), or holding the last time the digits made while they make
none (a clock typed 1, 9, 4, 5 shows ``00:19`` after the 4). The value is judged at the
entry's last digit, as usual."""

from __future__ import annotations

import re

from apbot.agent.belief import Belief
from apbot.agent.environment import Feedback, SimulatorEnvironment
from apbot.agent.episode import Episode, TaskContext, TraceEvent
from apbot.agent.pressing import typing
from apbot.agent.registry import get_method
from apbot.agent.session import Session
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from
from tests.helpers import run_checked as run

DISPENSER = """
controls:
  - {id: vol, label: VOL}
  - {id: k0, kind: key, label: "0"}
  - {id: k2, kind: key, label: "2"}
  - {id: k5, kind: key, label: "5"}
  - {id: go, label: POUR}
variables:
  volume: {type: numeric, unit: ml, ranges: [[100, 900, 10]], initial: 300, label: VOL,
           entry: {format: number, max_digits: 3, SHOWS}}
  pouring: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "POURING"}}
actions:
  press_vol: {control: vol}
  press_0: {control: k0, digit: 0}
  press_2: {control: k2, digit: 2}
  press_5: {control: k5, digit: 5}
  press_go: {control: go}
features:
  set_volume:
    - {actions: [press_vol]}
    - actions: [press_0, press_2, press_5]
      variable: volume
      effect: {press_0: digit, press_2: digit, press_5: digit}
  pour: [{actions: [press_go], variable: pouring, effect: toggle}]
display: {idle: "VOL {volume}", indicators: [pouring]}
"""

DIGITS = "".join(f'\n  - {{id: k{d}, kind: key, label: "{d}"}}' for d in range(10))
PRESSES = "".join(f"\n  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10))
KEYS = ", ".join(f"press_{d}" for d in range(10))

OVEN = f"""
controls:
  - {{id: delay, label: DELAY}}
  - {{id: clock, label: CLOCK}}
  - {{id: start, label: START}}{DIGITS}
variables:
  delay: {{type: time, ranges: [["01:00:00", "12:00:00", 1800]], initial: "01:00:00",
          format: "hh:mm", label: DELAY, entry: {{format: "hh:mm", DELAY_SHOWS}}}}
  clock: {{type: time, ranges: [["00:00:00", "23:59:00", 60]], initial: "00:00:00",
          format: CLOCK_FORMAT, entry: {{format: "hh:mm"}} CLOCK_SHOW}}
  running: {{type: discrete, values: ["off", "on"], show: {{"off": "", "on": "RUN"}}}}
actions:
  press_delay: {{control: delay}}
  press_clock: {{control: clock}}
  press_start: {{control: start}}{PRESSES}
features:
  set_delay:
    - {{actions: [press_delay]}}
    - {{actions: [{KEYS}], variable: delay}}
  set_clock:
    - {{actions: [press_clock]}}
    - {{actions: [{KEYS}], variable: clock}}
  start: [{{actions: [press_start], variable: running, effect: {{to: "on"}}}}]
display: {{idle: "IDLE", indicators: [running]}}
"""


def dispenser(shows: str) -> ApplianceModel:
    return model_from(DISPENSER.replace("SHOWS", f"shows: {shows}"))


def oven(
    delay_shows: str, clock_format: str, clock_show: str, idle: str = "{clock}"
) -> ApplianceModel:
    text = OVEN.replace("DELAY_SHOWS", f"shows: {delay_shows}").replace("IDLE", idle)
    text = text.replace("CLOCK_FORMAT", f'"{clock_format}"').replace("CLOCK_SHOW", clock_show)
    return model_from(text)


def mismatches(episode: Episode) -> list[TraceEvent]:
    """The checks that found the display other than the belief predicted."""
    return [e for e in episode.trace if e.kind == "check" and e.text == "mismatch"]


class FromTheLeft(SimulatorEnvironment):
    """A keypad that lays the digits in from the left of its ``shape`` (``--:--``) while
    they are typed, the places still to fill dashed."""

    def __init__(self, truth: ApplianceModel, shape: str) -> None:
        super().__init__(truth)
        self.shape = shape

    def step(self, action: str, seconds: float | None = None) -> Feedback:
        feedback = super().step(action, seconds)
        buffer = self.simulator.state.buffer
        if buffer:
            laid = re.sub("-", "{}", self.shape, count=len(buffer)).format(*buffer)
            feedback.text = re.sub(r"\d+(?::\d+)*", laid, feedback.text, count=1)
        return feedback


def test_a_delay_shifted_in_from_the_right_is_no_value_out_of_range() -> None:
    # 00:02 and 00:23 are digits on their way to 02:30, not delays below the hour
    episode, reached = run(
        oven("typed", "hh:mm", ', show: "{value}"'),
        oven("value", "hh:mm", ', show: "{value}"'),
        {"delay": "02:30", "running": "on"},
    )
    assert reached and episode.claimed_success, episode.failure
    assert not episode.repairs and not mismatches(episode), episode.trace


def run_from_the_left(
    truth: ApplianceModel, belief: ApplianceModel, goal: dict[str, str], shape: str
) -> Episode:
    """Run ``apbot`` from ``belief`` on ``truth`` typed from the left; the goal is reached."""
    env = FromTheLeft(truth, shape)
    context = TaskContext("unit", "test", "t", "", goal, belief, actions=tuple(env.actions))
    episode = get_method("apbot").run(context, env)
    assert env.simulator.satisfies(parse_goal(truth, goal)), episode.failure
    assert any("-" in (e.display or "") for e in episode.trace), "not typed from the left"
    return episode


def test_a_volume_laid_in_from_the_left_is_no_wrong_value() -> None:
    # 2-- and 25- on the way to 250 ml
    goal = {"volume": "250 ml", "pouring": "on"}
    episode = run_from_the_left(dispenser("typed"), dispenser("value"), goal, "---")
    assert episode.claimed_success and not mismatches(episode), episode.trace


def test_a_delay_laid_in_from_the_left_is_no_value_out_of_range() -> None:
    # 1-:--, 10:-- and 10:3- on the way to 10:30
    truth = oven("typed", "hh:mm", ', show: "{value}"')
    belief = oven("value", "hh:mm", ', show: "{value}"')
    episode = run_from_the_left(truth, belief, {"delay": "10:30", "running": "on"}, "--:--")
    assert episode.claimed_success and not mismatches(episode), episode.trace


def test_a_clock_that_keeps_its_last_time_is_judged_at_the_last_digit() -> None:
    # the clock shows its value (no typed entry), so 1, 9, 4 leaves 00:19 (01:94 is no
    # time); the belief prints it another way ("CLOCK 0:19"): what the panel really prints
    # is learnt from the entry's last digit ("19:45"), not from the digits on their way
    # (taken for minutes and seconds, "00:19" would make 19:45 out of reach)
    belief = oven("value", "h:mm", ", label: CLOCK", idle="")
    truth = oven("value", "hh:mm", ', show: "{value}"')
    episode, reached = run(truth, belief, {"clock": "19:45", "running": "on"})
    assert reached and episode.claimed_success, episode.failure
    assert not any("mm:ss" in repair for repair in episode.repairs), episode.repairs


def test_typing_accepts_both_fill_orders_and_nothing_else() -> None:
    belief = oven("value", "hh:mm", ', show: "{value}"')
    session = Session.__new__(Session)  # only the belief is read
    session.belief = Belief(belief)
    session.belief.set_pointer(("set_clock", 1), "170")
    for text in ("00:17", "01:70", "17:0-", "17:0_", "170"):
        assert typing(session, "clock", text), text
    for text in ("17:05", "PL170", "00:18", "1700", "17:--", "01:70.5"):
        assert not typing(session, "clock", text), text
