"""A STYLE key read as a switch: walking it shows the user's word among words the belief
cannot read, and they become the setting's values (the word reached, no false claim). A
display that shows only letters teaches nothing, and the run stops without claiming."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

TRUTH = """
controls: [{id: style, label: STYLE}]
variables:
  style:
    type: discrete
    values: [gouda, brie, feta]
    wrap: true
    label: STYLE
    show: {gouda: GOUDA, brie: BRIE, feta: FETA}
actions:
  press_style: {control: style}
features:
  style:
    - {actions: [press_style], variable: style, effect: next}
display:
  idle: "{style}"
"""

BELIEF = """
controls: [{id: style, label: STYLE}]
variables:
  style: {type: discrete, values: ["off", "on"], label: STYLE}
actions:
  press_style: {control: style}
features:
  style:
    - {actions: [press_style], variable: style, effect: toggle}
"""


def test_the_said_word_shown_by_the_walk_becomes_a_value_and_is_reached() -> None:
    episode, reached = run(model_from(TRUTH), model_from(BELIEF), {"style": "feta"})
    assert reached
    assert any("choices as shown" in note for note in episode.repairs)


def test_letters_that_only_may_stand_for_the_word_teach_nothing() -> None:
    truth = TRUTH.replace("{gouda: GOUDA, brie: BRIE, feta: FETA}", "{gouda: G, brie: B, feta: F}")
    episode, reached = run(model_from(truth), model_from(BELIEF), {"style": "feta"})
    assert not reached and not episode.claimed_success
