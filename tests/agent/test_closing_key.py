"""START that confirms the entry typed last instead of starting: an oven whose minute minder is
typed and then confirmed with START, read from a manual whose sentence about that confirmation
the reader missed. The agent learns the closing step from the START that showed the home screen,
leaves the entry by its own key (not by one that clears the cook time) and starts."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

_DIGITS = (
    "[press_0, press_1, press_2, press_3, press_4, press_5, press_6, press_7, press_8, press_9]"
)
_CONTROLS = """
controls: [{id: cook, label: COOK}, {id: minder, label: MINDER}, {id: grill, label: GRILL},
           {id: go, label: START},
           {id: k0, kind: key, label: "0"}, {id: k1, kind: key, label: "1"},
           {id: k2, kind: key, label: "2"}, {id: k3, kind: key, label: "3"},
           {id: k4, kind: key, label: "4"}, {id: k5, kind: key, label: "5"},
           {id: k6, kind: key, label: "6"}, {id: k7, kind: key, label: "7"},
           {id: k8, kind: key, label: "8"}, {id: k9, kind: key, label: "9"}]
"""
_ACTIONS = """
actions:
  press_cook: {control: cook}
  press_minder: {control: minder}
  press_grill: {control: grill}
  press_go: {control: go}
  press_0: {control: k0, digit: 0}
  press_1: {control: k1, digit: 1}
  press_2: {control: k2, digit: 2}
  press_3: {control: k3, digit: 3}
  press_4: {control: k4, digit: 4}
  press_5: {control: k5, digit: 5}
  press_6: {control: k6, digit: 6}
  press_7: {control: k7, digit: 7}
  press_8: {control: k8, digit: 8}
  press_9: {control: k9, digit: 9}
"""
_VARIABLES = """
variables:
  cook_time: {type: time, ranges: [["00:00:00", "00:59:59", 1]], format: "mm:ss",
              entry: {format: "mm:ss"}, label: COOK}
  minder: {type: time, ranges: [["00:00:00", "00:59:59", 1]], format: "mm:ss",
           entry: {format: "mm:ss"}, label: MINDER}
  grill: {type: discrete, values: ["off", "on"], show: {"off": "", "on": GRILL}}
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": HEATING}}
"""
_GUARDS = """
guards:
  - {name: heating, when: {running: "on"}, only: [press_go], display: HEATING}
display:
  idle: "READY"
"""

TRUTH = (
    _CONTROLS
    + _VARIABLES
    + _ACTIONS
    + f"""
features:
  cook:
    - {{actions: [press_cook]}}
    - {{actions: {_DIGITS}, variable: cook_time}}
  minder:
    - {{actions: [press_minder]}}
    - {{actions: {_DIGITS}, variable: minder}}
    - {{actions: [press_go], note: START confirms the minder}}
  grill:
    - {{actions: [press_grill], variable: grill, effect: toggle, reset: [cook_time]}}
  start:
    - {{actions: [press_go], variable: running, effect: toggle}}
"""
    + _GUARDS
)

# the reader missed "START confirms the minder" and that GRILL clears the cook time
BELIEF = TRUTH.replace(
    "\n    - {actions: [press_go], note: START confirms the minder}", ""
).replace(", reset: [cook_time]", "")


def test_start_that_confirms_the_minder_is_learnt_and_the_cooking_then_started() -> None:
    goal = {"cook_time": "00:12:00", "minder": "00:20:00", "running": "on"}
    episode, reached = run(model_from(TRUTH), model_from(BELIEF), goal)
    assert reached and episode.claimed_success
    assert any("press_go closes minder" in note for note in episode.repairs)


def test_a_start_that_starts_from_the_entry_teaches_no_closing_step() -> None:
    """Where START does start the cooking straight after the minder's digits, the belief was
    right: nothing is learnt and the plan is the belief's."""
    goal = {"cook_time": "00:12:00", "minder": "00:20:00", "running": "on"}
    episode, reached = run(model_from(BELIEF), model_from(BELIEF), goal)
    assert reached and episode.claimed_success
    assert not episode.repairs
