"""A setting the belief took for a lamp (its label lit for "on", dark for "off") that the panel
spells out on a screen of its own ("SOUND OFF") is no lamp: the label stood lit beside the off
value. Read as a lamp, its absence from every other screen would say "off" and let a claim rest
on nothing."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

COOKER = """
controls: [{id: dial}, {id: sound_key}]
variables:
  menu: {type: discrete, values: [white, cake], label: MENU, wrap: true}
  sound: SOUND
actions:
  turn_dial: {control: dial}
  hold_sound: {control: sound_key}
features:
  select_menu: [{actions: [turn_dial], variable: menu, effect: next}]
  sound: [{actions: [hold_sound], variable: sound, effect: toggle}]
display: DISPLAY
"""
TRUTH_SOUND = (
    '{type: discrete, values: ["on", "off"], show: {"on": "SOUND ON", "off": "SOUND OFF"}}'
)
BELIEF_SOUND = '{type: discrete, values: ["off", "on"], label: SOUND}'


def test_a_label_lit_beside_the_off_value_is_no_lamp() -> None:
    truth = model_from(
        COOKER.replace("SOUND", TRUTH_SOUND, 1).replace("DISPLAY", '{idle: "{menu}"}')
    )
    belief = model_from(
        COOKER.replace("SOUND", BELIEF_SOUND, 1).replace(
            "DISPLAY", '{idle: "{menu}", indicators: [sound]}'
        )
    )
    # the sound is on, the belief guesses off: the key meant to switch it on shows SOUND OFF
    episode, reached = run(truth, belief, {"menu": "cake", "sound": "on"})
    assert reached and episode.claimed_success
    assert "sound is spelt out on its own screen, not a lamp" in episode.repairs
