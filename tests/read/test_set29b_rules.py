"""Rules of the set29b session, each on a small manual of our own words: a power key held both
ways whose short press steps a setting of its own (and names it), a list in brackets after the
key's name, a quick-reference row holding one key to switch a thing on / off, and a reset
sentence whose only programme word is a key's printed name."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual
from apbot.read.value_lists import find_list

# a bicycle rear light: ⏻ held switches it, pressed steps the brightness; MODE steps the
# pattern, held switches the side lights
LIGHT = """
BRAKELITE bicycle rear light

THE BUTTONS
  ⏻      switch on and off (hold), brightness (short press)
  MODE   flash pattern (press), side lights (hold)

SWITCHING ON
  To switch on, hold ⏻ for two seconds. To switch off, hold ⏻ again.
  A short press of ⏻ does not switch the light on, so it cannot wake up in a pocket.

BRIGHTNESS
  While the light is on, each short press of ⏻ moves one step along the brightness scale:

     DIM  →  NORMAL  →  BRIGHT  →  back to DIM

FLASH PATTERN
  Hold MODE for three seconds again to go back to the steady light. The light returns to
  the pattern you had before.

SUMMARY
  | Goal                   | Action                                  |
  |------------------------|-----------------------------------------|
  | switch on / off        | hold ⏻ 2 s                              |
  | change the pattern     | press MODE (STEADY→PULSE→BLINK)         |
  | side lights on / off   | hold MODE 3 s                           |
"""

LIGHT_ACTIONS = ["hold_power", "press_power", "press_mode", "hold_mode"]


def _light() -> Any:
    return read_manual(LIGHT, LIGHT_ACTIONS).model


def _feature_of(model: Any, action: str) -> Any:
    return next(
        step for steps in model.features.values() for step in steps if action in step.actions
    )


def test_a_power_key_held_both_ways_leaves_its_short_press_to_a_setting() -> None:
    model = _light()
    power = _feature_of(model, "hold_power")
    assert power.variable == "power" and power.effect == "toggle"
    stepped = _feature_of(model, "press_power")
    assert stepped.variable == "brightness"
    assert list(model.variables["brightness"].values) == ["dim", "normal", "bright"]


def test_a_list_in_brackets_after_the_keys_name_leaves_the_name_out() -> None:
    assert find_list("press MODE (STEADY→PULSE→BLINK)") == (["STEADY", "PULSE", "BLINK"], "arrows")
    # no bracket: the list as before
    assert find_list("the next programme code (P0 → P1 → P2)") == (["P0", "P1", "P2"], "arrows")


def test_a_quick_reference_row_holding_one_key_switches_its_own_setting() -> None:
    model = _light()
    held = _feature_of(model, "hold_mode")
    assert held.variable == "side_lights" and held.effect == "toggle"
    assert list(model.variables["side_lights"].values) == ["off", "on"]


def test_a_reset_sentence_naming_only_a_keys_printed_name_resets_nothing() -> None:
    model = _light()
    pattern = _feature_of(model, "press_mode")
    assert not pattern.reset
