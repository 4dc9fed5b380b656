"""Rules of the set27b session (the twenty-seventh set's transfer press, powerchair controller and
tennis ball machine read as development data), each on a small manual in our own words: lamp
codes made of the setting's name and a letter (``prefixed_codes``), a key pair named for the two
ends of a legend of codes (``legend_ends``), a comparison table row read in its own model's
column (``model_rows``), half-second steps keeping a plain number of seconds (``part_seconds``),
a guessed range read as the levels of a counted bar legend (``bar_levels``)."""

from __future__ import annotations

from apbot.read import read_manual

# a garden sprinkler: a pattern lamp per NAME-letter code, a line per code saying its word
SPRINKLER = """
Aquaro S-5 sprinkler timer

KEYS: POWER, ARC

ARC PATTERN

Press ARC to step the pattern:

   off  →  ARC-F  →  ARC-H  →  ARC-Q  →  off

   ARC-F   full: a whole circle
   ARC-H   half: one side of the lawn only
   ARC-Q   quarter: a corner bed
"""
SPRINKLER_ACTIONS = ["press_power", "press_arc"]


def test_name_letter_codes_take_the_word_their_line_gives() -> None:
    """ "ARC-H   half: …" makes the value "half", shown ARC-H; "off" shows nothing."""
    model = read_manual(SPRINKLER, SPRINKLER_ACTIONS).model
    arc = model.variables["arc"]
    assert list(arc.values) == ["off", "full", "half", "quarter"]
    assert arc.show is not None and arc.show["half"] == "ARC-H" and arc.show["off"] == ""


# an amplifier with a tone pair named for the two ends of its legend
AMPLIFIER = """
Sonor A-20 practice amplifier

KEYS: POWER, TONE BASS, TONE TREBLE

TONE

The small screen shows the tone setting as a letter and a number:

   L2   strong bass boost
   L1   slight bass boost
   0    flat
   H1   slight treble boost
   H2   strong treble boost

Each press moves one step; the tone stops at L2 and at H2.
"""
AMPLIFIER_ACTIONS = ["press_power", "press_tone_bass", "press_tone_treble"]


def test_a_pair_named_for_a_legends_ends_steps_one_setting() -> None:
    """TONE BASS steps towards the rows glossed "bass", TONE TREBLE towards "treble"."""
    model = read_manual(AMPLIFIER, AMPLIFIER_ACTIONS).model
    tone = model.variables["tone"]
    assert [str(v) for v in tone.values] == ["l2", "l1", "0", "h1", "h2"]
    steps = [s for steps in model.features.values() for s in steps if s.variable == "tone"]
    assert steps and steps[0].effect == {"press_tone_treble": "next", "press_tone_bass": "prev"}


# a pump sold in three models, one specifications table, the manual about the middle one
PUMP = """
Fluvo dosing pumps

This manual covers the P-20.

P-20 PAUSE

Press PAUSE + or PAUSE − to set the pause between two doses, in half-second steps.

  Model             P-10          P-20           P-30
  ----------------  ------------  -------------  -------------
  Pause             5-30 s        1-20 s         1-60 s
  Weight            2 kg          2 kg           3 kg

The P-20 keeps the pause while switched off.
"""
PUMP_ACTIONS = ["press_power", "press_pause_up", "press_pause_down"]


def test_a_comparison_row_gives_its_own_models_range() -> None:
    """The P-20 column's 1-20 s, not the first model's 5-30 s."""
    whole = PUMP.replace("in half-second steps", "in steps of one second")
    pause = read_manual(whole, PUMP_ACTIONS).model.variables["pause"]
    assert [list(r) for r in pause.ranges] == [["00:00:01", "00:00:20", 1]]


def test_half_second_steps_keep_a_number_of_seconds() -> None:
    """ "in half-second steps" under a minute: a number of seconds by 0.5, not a m:ss time."""
    pause = read_manual(PUMP, PUMP_ACTIONS).model.variables["pause"]
    assert pause.type == "numeric"
    assert [list(r) for r in pause.ranges] == [[1, 20, 0.5]]


# a ceiling fan remote with a five-lamp bar and no figures
FAN = """
Ventaro CF-3 ceiling fan remote

KEYS: POWER, SPEED DOWN, SPEED UP

FAN SPEED

The remote has no screen. The speed lamps show the speed by how many are lit:

    ●○○○○  level 1 - gentle breeze
    ●●○○○  level 2
    ●●●○○  level 3
    ●●●●○  level 4
    ●●●●●  level 5 - full speed

SPEED UP raises the speed one level, SPEED DOWN lowers it.
"""
FAN_ACTIONS = ["press_power", "press_speed_up", "press_speed_down"]


def test_a_counted_bar_legend_gives_the_levels() -> None:
    """Levels 1–5, each shown as its bar, not a guessed 0–10 range."""
    model = read_manual(FAN, FAN_ACTIONS).model
    speed = model.variables["speed"]
    assert [str(v) for v in speed.values] == ["1", "2", "3", "4", "5"]
    assert speed.show is not None and speed.show["3"] == "●●●○○"


# a bicycle light remote: a key per side, one side blinking at a time
BIKE = """
Lumo R-2 bicycle light remote

KEYS: POWER, ◄, ►

  ◄   left signal
  ►   right signal
  The ◄ and ► lamps on the remote blink with the signals.

TURN SIGNALS

Press ◄ to blink the left signal; press ◄ again to stop it. Press ► for the right signal.
Only one side can blink: pressing ► while the left signal blinks stops the left one.
"""
BIKE_ACTIONS = ["press_power", "press_left", "press_right"]


def test_two_side_keys_are_one_setting_of_three_values() -> None:
    """◄ / ► set one signal, off / left / right, each key back to off; shown as its lamp."""
    model = read_manual(BIKE, BIKE_ACTIONS).model
    signal = model.variables["signal"]
    assert list(signal.values) == ["off", "left", "right"]
    assert signal.show == {"off": "", "left": "◄", "right": "►"}
    steps = [s for steps in model.features.values() for s in steps if s.variable == "signal"]
    assert sorted(a for s in steps for a in s.actions) == ["press_left", "press_right"]
