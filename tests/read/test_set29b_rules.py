"""Rules of the set29b session, each on a small manual of our own words: a power key held both
ways whose short press steps a setting of its own (and names it), a list in brackets after the
key's name, and a quick-reference row holding one key to switch a thing on / off."""

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


# a dosing pump: a thumb wheel over a range-and-step table in microlitres, a comparison table of
# models with a row of step sizes, and a rate key whose run of figures says where it wraps
DOSER = """
DOSAMAT bench dosing pump

MODELS
  | Feature          | D-10          | D-50           |
  |------------------|---------------|----------------|
  | Volume range       | 1 – 10 mL     | 20 – 500 µL    |
  | Dial increments  | 0.1 / 0.5 mL  | 2 / 5 / 10 µL  |

This leaflet covers the D-50.

CONTROLS
  ⏻       on and off
  RATE    pump rate
  DIAL    the volume

THE VOLUME
  Turn the DIAL to set the volume. How far one click moves it depends on the volume:

     Volume range         One click
     20 – 100 µL        2 µL
     100 – 200 µL       5 µL
     200 – 500 µL       10 µL

PUMP RATE
  Each press of RATE raises the rate by one: 1, 2, 3, 4, and after 4 back to 1.
"""

DOSER_ACTIONS = ["press_power", "press_rate", "turn_dial_up", "turn_dial_down"]


def _doser() -> Any:
    return read_manual(DOSER, DOSER_ACTIONS).model


def test_a_row_of_step_sizes_gives_the_dial_no_list_of_values() -> None:
    model = _doser()
    dial = _feature_of(model, "turn_dial_up")
    assert model.variables[dial.variable].type == "numeric"
    assert not any("d_10" in n or "d_50" in n for n in model.variables)


def test_a_range_and_step_table_in_microlitres_gives_every_row_its_step() -> None:
    dose = _doser().variables[_feature_of(_doser(), "turn_dial_up").variable]
    assert dose.unit == "µl"
    assert [list(r) for r in dose.ranges] == [[20, 100, 2], [100, 200, 5], [200, 500, 10]]


def test_a_run_of_figures_that_says_where_it_wraps_is_the_keys_cycle() -> None:
    assert find_list("raises it by one: 1, 2, 3, 4, and after 4 back to 1") == (
        ["1", "2", "3", "4"],
        "list",
    )
    model = _doser()
    rate = _feature_of(model, "press_rate")
    assert rate.effect == "next"
    assert [list(r) for r in model.variables[rate.variable].ranges] == [[1, 4, 1]]


def test_a_dose_said_in_microlitres_is_read_as_microlitres() -> None:
    from apbot.read.number_tokens import tokenize

    assert [t.text for t in tokenize("dose 250 µL")] == ["dose", "250", "microlitre"]


# a drum machine: kit banks stepped with a pair of keys, written as letters with an ellipsis
DRUMS = """
BEATBOX 8 drum machine

KITS
  The machine has kits in banks. Step the bank with KIT ▲ (A → B → … → E → A) or KIT ▼ (the
  other way round).
"""

DRUMS_ACTIONS = ["press_kit_up", "press_kit_down"]


def test_letters_stepped_with_an_ellipsis_are_the_pairs_values() -> None:
    assert find_list("KIT ▲ (A → B → … → E → A)") == (["A", "B", "C", "D", "E"], "arrows")
    model = read_manual(DRUMS, DRUMS_ACTIONS).model
    kit = _feature_of(model, "press_kit_up")
    assert [str(v).upper() for v in model.variables[kit.variable].values] == list("ABCDE")


def test_microlitres_are_a_thousandth_of_a_millilitre() -> None:
    from apbot.model.values import unit_of

    assert unit_of("µl") == ("volume", 0.001) and unit_of("microlitres") == ("volume", 0.001)
