"""The closed loop recovers when a key adds more than the belief says (issue 13, agent7b).

A read belief gave the minute key of a delay-start one minute per press, the manual having
said only "adjust with HOUR and MIN"; the panel moves a quarter of an hour per press. The walk
shows the stride; the minutes in between are then no value any key reaches, and the repair must
drop them instead of being refused for leaving them unreachable."""

from __future__ import annotations

import pytest

from apbot.agent.environment import FeedbackMode
from tests.helpers import model_from
from tests.helpers import run_checked as run

OVEN = """
controls: [{id: delay, label: DELAY}, {id: hour, label: HOUR}, {id: mins, label: MIN},
           {id: go, label: GO}]
variables:
  delay_end: {type: time, format: "hh:mm", ranges: [["00:00:00", "23:45:00", 900]],
              initial: "08:00:00", wrap: true, show: "END {value}"}
  baking: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "BAKE"}}
actions: {press_delay: {control: delay}, press_hour: {control: hour}, press_min: {control: mins},
          press_go: {control: go}}
features:
  delay:
    - {actions: [press_delay]}
    - actions: [press_hour, press_min]
      variable: delay_end
      effect: {press_hour: {add: 3600}, press_min: {add: 900}}
  go: [{actions: [press_go], variable: baking, effect: {to: "on"}}]
display: {idle: "OVEN", indicators: [baking]}
"""

# what a reader guessed: one minute per press of MIN, every minute of the day a value
GUESSED = OVEN.replace(
    'ranges: [["00:00:00", "23:45:00", 900]]', 'ranges: [["00:00:00", "23:59:00", 60]]'
)
GUESSED = GUESSED.replace("press_min: {add: 900}", "press_min: {add: 60}")


@pytest.mark.parametrize("feedback", ["display", "values"])
def test_a_stride_seen_on_the_panel_drops_the_minutes_no_key_reaches(
    feedback: FeedbackMode,
) -> None:
    episode, reached = run(
        model_from(OVEN), model_from(GUESSED), {"delay_end": "11:45:00", "baking": "on"}, feedback
    )
    assert reached and episode.claimed_success, episode.failure
    assert any("adds 900" in r for r in episode.repairs), episode.repairs


# the same panel, its quarter hours offset by five minutes (the grid runs through the values
# the panel shows, not through midnight)
OFFSET = OVEN.replace('[["00:00:00", "23:45:00", 900]]', '[["00:05:00", "23:50:00", 900]]')
OFFSET = OFFSET.replace('initial: "08:00:00"', 'initial: "08:05:00"')


def test_the_strides_run_through_the_values_shown() -> None:
    episode, reached = run(
        model_from(OFFSET), model_from(GUESSED), {"delay_end": "11:50:00", "baking": "on"}
    )
    assert reached and episode.claimed_success, episode.failure
    assert any("adds 900" in r for r in episode.repairs), episode.repairs


# a timer whose stride changes: a minute a press up to ten minutes, then five; the reader
# guessed a minute a press all the way. The walk shows both strides; snapping the domain to the
# larger one would drop minutes the panel has just shown (3 min, 45 min) and invent others.
TIMER = """
controls: [{id: time, label: TIME}, {id: go, label: GO}]
variables:
  cook: {type: time, format: "mm:ss", ranges: RANGES, initial: "START", wrap: true,
         show: "T {value}"}
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "RUN"}}
actions: {press_time: {control: time}, press_go: {control: go}}
features:
  t: [{actions: [press_time], variable: cook, effect: EFFECT}]
  go: [{actions: [press_go], variable: running, effect: {to: "on"}}]
display: {idle: "READY", indicators: [running]}
"""
TWO_STRIDES = '[["00:01:00", "00:10:00", 60], ["00:10:00", "01:00:00", 300]]'


@pytest.mark.parametrize(("start", "goal"), [("00:30:00", "00:03:00"), ("00:08:00", "00:45:00")])
def test_a_walk_whose_stride_changes_drops_no_value_it_showed(start: str, goal: str) -> None:
    truth = TIMER.replace("RANGES", TWO_STRIDES).replace("EFFECT", "next")
    belief = TIMER.replace("RANGES", '[["00:01:00", "01:00:00", 60]]')
    belief = belief.replace("EFFECT", "{press_time: {add: 60}}")
    episode, _ = run(
        model_from(truth.replace("START", start)),
        model_from(belief.replace("START", start)),
        {"cook": goal, "running": "on"},
    )
    assert not any("adds 300" in r for r in episode.repairs), episode.repairs
    assert "not a value the model knows" not in (episode.failure or ""), episode.failure
