"""An on/off lamp the belief prints other than the panel: learnt from the press that switched it
(a lamp word with a qualifier that changes with the state; a sign of running that is another
word than the one the reader took)."""

from __future__ import annotations

from apbot.agent.relit import new_sign, printed_words
from tests.helpers import model_from
from tests.helpers import run_checked as run

TRUTH = """
controls: [{id: power, label: POWER}, {id: up, label: UP}, {id: guard, label: GUARD},
           {id: go, label: GO}]
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "{level}"}}
  level: {type: numeric, ranges: [[1, 5, 1]], initial: 1, show: "L{value}"}
  shield:
    type: discrete
    values: [shut, open]
    show: {shut: SHIELD AMBER, open: SHIELD BLUE}
  running:
    type: discrete
    values: ["off", "on"]
    show: {"off": "L{level}", "on": "SPRAYING"}
actions:
  press_power: {control: power}
  press_up: {control: up}
  hold_guard: {control: guard, skill: hold, seconds: 2}
  press_go: {control: go}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle, set: {shield: shut}}
  level:
    - {actions: [press_up], variable: level, effect: next}
  open_shield:
    - {actions: [hold_guard], variable: shield, effect: {to: open}}
  go:
    - {actions: [press_go], variable: running, effect: toggle, set: {shield: shut}}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
  - {name: shield, when: {shield: shut, running: "off"}, only: [press_power, press_up, hold_guard],
     display: SHIELD AMBER}
display:
  idle: "L{level}"
  indicators: [shield, running]
"""

BELIEF = """
controls: [{id: power, label: POWER}, {id: guard, label: SHIELD}, {id: go, label: GO}]
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": ""}}
  shield_lock: {type: discrete, values: ["off", "on"], label: SHIELD,
                show: {"off": "", "on": SHIELD}}
  running: {type: discrete, values: ["off", "on"], label: RUN, show: {"off": "", "on": RINSE}}
actions:
  press_power: {control: power}
  hold_guard: {control: guard, skill: hold, seconds: 2}
  press_go: {control: go}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  shield_lock:
    - {actions: [hold_guard], variable: shield_lock, effect: toggle}
  start:
    - {actions: [press_go], variable: running, effect: toggle}
guards:
  - {name: shield, when: {shield_lock: "on"}, only: [hold_guard], display: SHIELD}
  - {name: power off, when: {power: "off"}, only: [press_power], hide: true}
"""


def test_a_lamp_word_whose_qualifier_changes_and_a_new_sign_of_running_are_learnt() -> None:
    """The belief lights "SHIELD" for the latch (the panel: SHIELD AMBER / SHIELD BLUE) and
    takes a rinsing word for the sign of running (the panel prints SPRAYING): releasing the
    latch and starting are read back only once both are learnt from the presses."""
    truth = model_from(TRUTH)
    belief = model_from(BELIEF)
    episode, reached = run(truth, belief, {"running": "on"})
    assert reached
    assert any("'SHIELD BLUE'" in note for note in episode.repairs)
    assert any("'SPRAYING'" in note for note in episode.repairs)


def test_a_programme_name_coming_back_is_no_new_sign_of_a_lamp() -> None:
    """Switching a lamp off can bring back a screen that names the programme (``grill 180``):
    a value of one of the belief's lists is a word it knows, not the lamp's new sign."""
    belief = model_from(
        BELIEF.replace(
            "  power: {type",
            "  mode: {type: discrete, values: [bake, grill]}\n  power: {type",
        ).replace(
            "  start:\n",
            "  mode:\n    - {actions: [press_go], variable: mode, effect: next}\n  start:\n",
        ),
        check=False,
    )
    assert new_sign("ROT", "ROT", "grill 180", printed_words(belief)) is None
