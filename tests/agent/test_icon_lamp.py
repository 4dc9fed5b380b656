"""An on/off setting whose lamp is an icon, not a word: the press that switches it on brings a
pictogram to the display, which the belief (with no lamp for it) learns as the sign of "on"."""

from __future__ import annotations

from apbot.agent.relit import new_word
from apbot.agent.value_words import is_icon, names_value
from tests.helpers import model_from
from tests.helpers import run_checked as run

# A bird feeder: a perch size on its own screen, and a "winter" heater lit as a snowflake.
TRUTH = """
controls: [{id: perch, label: PERCH}, {id: winter, label: WINTER}]
variables:
  perch: {type: discrete, values: [small, large], show: {small: "P1", large: "P2"}}
  winter: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "❄"}}
actions: {press_perch: {control: perch}, press_winter: {control: winter}}
features:
  perch: [{actions: [press_perch], variable: perch, effect: next}]
  winter: [{actions: [press_winter], variable: winter, effect: toggle}]
display: {idle: "{perch}", indicators: [winter]}
"""

# The belief read the heater as a setting but not its lamp.
BELIEF = """
controls: [{id: perch, label: PERCH}, {id: winter, label: WINTER}]
variables:
  perch: {type: discrete, values: [small, large], show: {small: "P1", large: "P2"}}
  winter: {type: discrete, values: ["off", "on"]}
actions: {press_perch: {control: perch}, press_winter: {control: winter}}
features:
  perch: [{actions: [press_perch], variable: perch, effect: next}]
  winter: [{actions: [press_winter], variable: winter, effect: toggle}]
display: {idle: "{perch}"}
"""


def test_an_icon_is_a_lamp_and_says_on() -> None:
    assert is_icon("❄") and is_icon("☾")
    assert not is_icon("▮▮▯") and not is_icon("–") and not is_icon("%") and not is_icon("A")
    assert new_word("P1", "❄  P1", set()) == "❄"
    assert names_value(None, "winter", "❄", "on", ["off", "on"])
    assert not names_value(None, "winter", "❄", "off", ["off", "on"])
    assert not names_value(None, "mode", "❄", "cold", ["hot", "cold"])  # not an on/off setting


def test_the_icon_lamp_is_learnt_from_the_press_that_lit_it() -> None:
    episode, reached = run(
        model_from(TRUTH), model_from(BELIEF), {"winter": "on", "perch": "large"}
    )
    assert reached, episode.failure
    assert episode.claimed_success, episode.failure
    assert any("'❄'" in note for note in episode.repairs), episode.repairs
