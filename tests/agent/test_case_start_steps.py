"""A programme's start of its own setting, learnt from a look whose entry press the belief
says steps the value: the start is where that step would have come from."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

DRYER = """
controls: [{id: mode}, {id: dry}, {id: up}, {id: down}]
variables:
  mode: {type: discrete, values: [rinse, dry], label: MODE}
  dry_time:
    type: numeric
    unit: min
    label: DRY
    wrap: true
    depends_on: mode
    cases:
      rinse: {ranges: [[0, 0, 1]]}
      dry: {ranges: [[20, 60, 5]]STARTS}
actions:
  press_mode: {control: mode}
  press_dry: {control: dry}
  press_up: {control: up}
  press_down: {control: down}
features:
  mode: [{actions: [press_mode], variable: mode, effect: next}]
  dry_time:
    - {actions: [press_dry, press_up, press_down], variable: dry_time, on_entry: ENTRY,
       effect: {press_dry: next, press_up: next, press_down: prev}}
display:
  idle: "{mode}"
"""


def test_a_look_the_belief_thinks_steps_the_value_still_corrects_the_guessed_start() -> None:
    # the panel starts drying at 40 min and its DRY key first only shows it; the reader took
    # the first value of the range (20, the goal's) and believed DRY steps it at once (every
    # key moves it: it wraps), so the look showing 40 was "one step from 35" — either way not
    # 20, and choosing the mode again (the belief's cheap way back to 20) would loop
    truth = model_from(DRYER.replace("STARTS", ", initial: 40").replace("ENTRY", "show"))
    belief = model_from(DRYER.replace("STARTS", "").replace("ENTRY", "apply"))
    episode, reached = run(truth, belief, {"mode": "dry", "dry_time": 20})
    assert reached
    assert any(note.startswith("dry_time starts at") for note in episode.repairs)
