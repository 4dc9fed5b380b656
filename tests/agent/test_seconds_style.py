"""A short duration the panel prints in seconds ("t45 s") where the belief read a clock style:
the display learner tries every time style, seconds among them, on the walk's texts."""

from __future__ import annotations

from apbot.model.values import format_time
from tests.helpers import model_from
from tests.helpers import run_checked as run

# A rinse pump: its run time steps 15 s, 30 s, 45 s, 60 s and shows as "R30 s".
TRUTH = """
controls: [{id: run, label: RUN}]
variables:
  run_time: {type: time, format: "s", ranges: [["00:00:15", "00:01:00", 15]],
             initial: "00:00:30", show: "R{value}", wrap: true}
actions: {press_run: {control: run}}
features:
  run_time: [{actions: [press_run], variable: run_time, effect: next}]
display: {idle: "R{run_time}"}
"""

# The belief read the same steps but took them for minutes:seconds ("00:30").
BELIEF = """
controls: [{id: run, label: RUN}]
variables:
  run_time: {type: time, format: "mm:ss", ranges: [["00:00:15", "00:01:00", 15]],
             initial: "00:00:30", wrap: true}
actions: {press_run: {control: run}}
features:
  run_time: [{actions: [press_run], variable: run_time, effect: next}]
display: {idle: "{run_time}"}
"""


def test_seconds_are_a_time_style() -> None:
    assert format_time(45, "s") == "45 s"


def test_a_run_time_shown_in_seconds_is_learnt_from_the_walk() -> None:
    episode, reached = run(model_from(TRUTH), model_from(BELIEF), {"run_time": "00:00:45"})
    assert reached, episode.failure
    assert episode.claimed_success, episode.failure
    assert any("(s)" in note for note in episode.repairs), episode.repairs
