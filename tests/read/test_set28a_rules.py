"""Rules of the set28a session, each on a small manual of our own words: a model-comparison
table's first column is no list of values (``evidence_lists``, ``model_columns``), named bands
of a scale are no range and a range stated with a unit no pattern knows is (``named_bands``,
``values_stated``), a hold said as "Held for N s it changes X" (``names_meaning``), an icon
key named by a compound noun and its levels written as its name and a number
(``text_sign_keys``, ``legend_compounds``, ``label_levels``), three-letter display codes a
table spells out (``code_rows``), a second function reached by two keys together
(``pair_lists``), a guessed on/off whose section shows two states (``shown_pairs``) and a
sentence of factory settings (``initials``)."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual

# a practice pad with a click: a comparison of three models, tempo bands, a SHIFT function
PAD = """
BEATBOX BX-2 practice pad

PAD VERSIONS

  +----------------+---------+---------+---------+
  |                | BX-1    | BX-2    | BX-3    |
  +----------------+---------+---------+---------+
  | Pad diameter   | 20 cm   | 25 cm   | 30 cm   |
  | Battery life   | 10 h    | 20 h    | 30 h    |
  | Headphone jack | no      | yes     | yes     |
  +----------------+---------+---------+---------+

1  KEYS

  POWER   switches the pad on and off
  PAD     chooses the pad sound
  SPEED   sets the click speed
  SHIFT   hold it and press SPEED for the second function
  -  +    change the value shown

2  PAD SOUND

  Press PAD, then + or - to step through the sounds, 1 to 12.

3  SPEED

  1. Press SPEED.
  2. + or - changes the speed by 2 BPM.
  3. The range is 40 BPM to 208 BPM.

  Speed bands for reference
     Lento 45–60 · Andante 72–108 · Allegro 120–168

4  SECOND FUNCTION

  Accent  (SHIFT + SPEED)

     The display shows the accent, e.g. ACC NONE. Step with + and -:

        ACC NONE    no accent
        ACC FIRST   first beat of the bar
        ACC EVERY   every beat

5  FACTORY SETTINGS

  Factory settings: pad 1, 100 BPM, accent NONE.
"""

PAD_ACTIONS = [
    "press_power",
    "press_pad",
    "press_speed",
    "shift_speed",
    "press_minus",
    "press_plus",
]


def _read(text: str, actions: list[str]) -> dict[str, Any]:
    return read_manual(text, actions).model.model_dump(mode="json", exclude_none=True)


def test_a_model_comparison_table_gives_no_values() -> None:
    """The rows of "| | BX-1 | BX-2 | BX-3 |" under a heading naming PAD are what the models
    differ in, not pad sounds: the pad is the numbered run its section gives."""
    model = _read(PAD, PAD_ACTIONS)
    pad = model["variables"]["pad"]
    assert pad["type"] == "numeric" and pad["ranges"][0][:2] == [1, 12]


def test_named_bands_are_no_range_and_a_stated_range_with_its_unit_is() -> None:
    """ "Lento 45–60 · Andante 72–108" names parts of the scale; "The range is 40 BPM to
    208 BPM" is the setting's, and "by 2 BPM" its step."""
    model = _read(PAD, PAD_ACTIONS)
    assert model["variables"]["speed"]["ranges"] == [[40, 208, 2]]


def test_a_second_function_takes_its_heading_and_list() -> None:
    """ "Accent (SHIFT + SPEED)" and the ACC lines: a setting of its own, stepped by - / +."""
    model = _read(PAD, PAD_ACTIONS)
    accent = model["variables"]["accent"]
    assert accent["values"] == ["none", "first", "every"]
    assert accent["show"]["first"] == "ACC FIRST"
    steps = model["features"]["accent"]
    assert steps[0]["actions"] == ["shift_speed"] and steps[1]["variable"] == "accent"


def test_a_factory_settings_sentence_gives_start_values() -> None:
    model = _read(PAD, PAD_ACTIONS)
    assert model["variables"]["speed"]["initial"] == 100
    assert model["variables"]["pad"]["initial"] == 1


# a star-party red torch: an icon key, levels written with it, a hold, codes in a table
TORCH = """
NIGHTOWL red torch

1  THE KEYS

  (A) ☼ Backlight. Steps the keypad light.
  (B) MODE. Opens the beam menu. Held for 2 seconds it changes the filter; see section 4.
  (C) BEAM. Chooses the beam.

2  KEYPAD LIGHT

  The keypad is lit at one of three levels:

     ☼1  faint     ☼2  soft     ☼3  full

  Press ☼ to go up one level. After ☼3 the next press returns to ☼1.

3  BEAM

  Each press of BEAM: SPO → FLO → OFF → SPO …

     Display      Beam          Use
     ---------    ----------    ------------------------
     BEAM SPO     spot          reading a chart
     BEAM FLO     flood         walking to the car
     BEAM OFF     no beam       saving the battery

4  FILTER

  Hold MODE for 2 seconds. The screen shows:

     FLT R    deep red filter
     FLT A    amber filter

  Each hold swaps the filter.

5  FACTORY SETTINGS

  Factory settings: beam SPO, backlight 2, child lock off.
"""

TORCH_ACTIONS = ["press_light", "hold_mode", "press_beam"]


def test_an_icon_key_named_by_a_compound_and_its_levels() -> None:
    """ "(A) ☼ Backlight." names the ``light`` key and its setting; "☼1 faint ☼2 soft ☼3
    full" are its levels, each press the next."""
    model = _read(TORCH, TORCH_ACTIONS)
    light = model["variables"]["backlight"]
    assert light["type"] == "numeric" and light["ranges"][0][:2] == [1, 3]
    assert light["initial"] == 2
    assert model["features"]["set_backlight"][0]["actions"] == ["press_light"]


def test_three_letter_codes_a_table_spells_out() -> None:
    model = _read(TORCH, TORCH_ACTIONS)
    beam = model["variables"]["beam"]
    assert beam["values"] == ["spot", "flood", "off"]
    assert beam["show"]["flood"] == "BEAM FLO"


def test_a_hold_said_of_the_key_names_its_setting_and_its_two_states() -> None:
    """ "Held for 2 seconds it changes the filter" and the section's FLT R / FLT A lines."""
    model = _read(TORCH, TORCH_ACTIONS)
    flt = model["variables"]["filter"]
    assert flt["values"] == ["deep red", "amber"]
    assert flt["show"] == {"deep red": "FLT R", "amber": "FLT A"}


def test_a_start_value_ending_a_sentence_is_read_as_itself() -> None:
    """ "child lock off." at a sentence's end is off, not the LOCK its display shows."""
    text = """
SNUG pet door

  LOCK (hold 3 s) switches the child lock on or off; LOCK appears while it is on.
  DOOR opens and closes the flap.

  The door starts with these settings: flap closed, child lock off.
"""
    model = _read(text, ["hold_lock", "press_door"])
    locks = [v for v in model["variables"].values() if v.get("initial") is not None]
    assert locks and all(v["initial"] == "off" for v in locks if v["values"] == ["off", "on"])


def test_a_stated_unit_span_with_decimal_commas_is_read_not_a_crash() -> None:
    """The read fuzz found it: a span stated with a decimal comma ("between 24rpm and
    1,5rpm") had its ends compared as floats before the comma became a point: ValueError."""
    manual = """
Drehteller D-1 turntable

The SPEED can be set between 0,5rpm and 2,5rpm with the SPEED key.

The WEIGHT can be set between 24rpm and 1,5rpm.
"""
    names = ["press_speed_button", "press_weight_button", "press_start_button"]
    model = read_manual(manual, names).model
    assert set(model.actions) == set(names)
