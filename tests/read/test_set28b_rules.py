"""Rules of the set28b session, each on a small manual of our own words: a cycle of figures
each printed with the setting's word ("1 BEEP → 2 BEEP"), a pair's own quantity named before
"up and down", ranges told by where the stepping stops, ranges told in parts that continue each
other, a number typed on the keypad taking every whole number, a key that confirms "a typed
<noun>", two names joined by a two-way arrow between their signs, a model variant's one-letter
suffix in a comparison table, a power key whose appliance "starts in" a mode, bars printed
after "level N", and a display that goes back to its view without resetting anything."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import all_values
from apbot.read import read_manual
from apbot.read.model_columns import is_type_number
from apbot.read.value_lists import find_list

# an aquarium lamp: a pair that steps the brightness alone, and a preset after COLOUR
LAMP = """
GLOWBOX aquarium lamp

KEYS
  1  POWER     Switches the lamp on and off.
  2  COLOUR    Opens the colour preset.
  3  ▲ / ▼     Brightness up and down; after COLOUR, preset up and down.

BRIGHTNESS
 The brightness is shown as a bar of six blocks:

     BRT ■□□□□□   level 1 (dimmest)
     BRT ■■■□□□   level 3
     BRT ■■■■■■   level 6 (brightest)

 Press ▲ to add a block and ▼ to remove one. Nothing happens beyond 1 or 6.

COLOUR
 1. Press COLOUR. The display shows the preset, e.g. COL 3.
 2. Press ▲ or ▼ to change it (1 to 9).

ALARM BEEPS
 BEEP sets how many beeps the alarm gives. Each press selects the next:
 1 BEEP → 2 BEEP → 3 BEEP → 1 BEEP …  (factory: 2 BEEP)
"""

LAMP_ACTIONS = ["press_power", "press_colour", "press_up", "press_down", "press_beep"]


def _lamp() -> Any:
    return read_manual(LAMP, LAMP_ACTIONS).model


def test_a_cycle_of_figures_printed_with_the_settings_word_keeps_the_first_figure() -> None:
    assert find_list("Each press: 1 BEEP → 2 BEEP → 3 BEEP → 1 BEEP …") == (
        ["1 BEEP", "2 BEEP", "3 BEEP"],
        "arrows",
    )
    model = _lamp()
    beep = next(n for n in model.variables if "beep" in n)
    assert [float(v) for v in all_values(model.variables[beep])] == [1.0, 2.0, 3.0]


def test_a_pair_named_before_up_and_down_steps_its_own_quantity_alone() -> None:
    model = _lamp()
    assert "brightness" in model.variables
    alone = [
        st
        for f in model.features.values()
        if len(f) == 1
        for st in f
        if st.variable == "brightness"
    ]
    assert alone and set(alone[0].actions) == {"press_up", "press_down"}


def test_the_ends_where_stepping_stops_are_the_range() -> None:
    from apbot.read.end_stops import end_stops

    assert end_stops("Nothing happens beyond 1 or 6.") is not None
    assert end_stops("At 0 and at 40 further turns change nothing.") is not None
    assert end_stops("Most engines begin to move at step 1 or 2.") is None
    model = _lamp()
    values = [str(v) for v in all_values(model.variables["brightness"])]
    assert values == ["1", "2", "3", "4", "5", "6"]


def test_bars_printed_after_level_figures_show_every_level() -> None:
    var = _lamp().variables["brightness"]
    assert var.show is not None
    assert var.show["2"] == "■■□□□□"


# a scanner: channels typed on a keypad, told in two parts; ENTER only confirms; an endless
# knob whose squelch stops at both ends; a mode it always starts in
SCANNER = """
SKYBAND SR-7 radio scanner

1  MODELS

  | Feature   | SR-7    | SR-7 X   | SR-9 PRO |
  | Bands     | 2       | 3        | 5        |
  | Memories  | 50      | 100      | 500      |

  This booklet covers the SR-7. The SR-7 is sold in black, the SR-7 X in grey.
  SR-7 owners: keep the receipt. SR-7 spare parts are listed on the back.

2  KEYS

  ⏻        On / off.
  CH       Selects a channel by its number.
  ENTER    Confirms a typed channel.
  SQ       Endless knob with clicks.
  0 - 9    Number keys.

3  SWITCHING ON

  Press ⏻. The display lights up.
  Press ⏻ again to switch it off; the display goes dark.
  The scanner always starts in SCAN mode.

4  CHANNELS

  Press CH to choose a channel. Channels 1 to 99 are local ones. Channels 100 to 999 are
  shared ones. Type the channel number with the number keys, then press ENTER.

5  SQUELCH

  Turn SQ one click per level. At 0 and at 15 further clicks do nothing.
"""

SCANNER_ACTIONS = [
    "press_power",
    "press_ch",
    "press_enter",
    "turn_sq_cw",
    "turn_sq_ccw",
    *[f"press_{d}" for d in range(10)],
]


def _scanner() -> Any:
    return read_manual(SCANNER, SCANNER_ACTIONS).model


def test_ranges_in_parts_that_continue_each_other_are_one_typed_range() -> None:
    model = _scanner()
    ch = model.variables["ch"]
    values = list(all_values(ch))
    assert values[0] == 1 and values[-1] == 999
    assert 47 in values and 512 in values  # (typed: every whole number, not a guessed step)


def test_a_key_that_confirms_a_typed_number_is_no_setting() -> None:
    model = _scanner()
    assert "enter" not in model.variables
    assert any(st.actions == ["press_enter"] for f in model.features.values() for st in f[1:])


def test_an_endless_knob_whose_value_stops_at_both_ends_does_not_wrap() -> None:
    var = _scanner().variables["sq"]
    assert [v for v in all_values(var)][-1] == 15
    assert not var.wrap


def test_a_power_key_the_appliance_starts_in_a_mode_after_is_a_power_switch() -> None:
    model = _scanner()
    assert "power" in model.variables
    assert any(g.name == "power off" for g in model.guards)


def test_a_one_letter_variant_is_a_type_number() -> None:
    assert is_type_number("SR-7 X")
    assert is_type_number("HT-28")


def test_two_names_whose_signs_point_at_the_two_way_arrow() -> None:
    assert find_list("Press TURN to reverse it:  UP ►  ↔  ◄ DN.") == (["UP", "DN"], "arrows")


# a display's view coming back is no reset of the settings
HEATER = """
WARMLINE panel heater

KEYS
  MODE    Selects the mode: ECO → COMFORT → BOOST → ECO …
  FAN     Fan speed: LOW → HIGH → LOW …
  ▲ / ▼   Temperature up and down.

The temperature runs from 10 to 30 °C.
After 5 seconds without a key, the display returns to the mode name and ▲ / ▼ go back to the
temperature.
"""


def test_a_display_going_back_to_its_view_resets_nothing() -> None:
    model = read_manual(HEATER, ["press_mode", "press_fan", "press_up", "press_down"]).model
    resets = [st.reset for f in model.features.values() for st in f if st.reset]
    assert not resets
