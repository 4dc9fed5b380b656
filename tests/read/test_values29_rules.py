"""Rules of the values29 session, each on a small manual of our own words: a range written with
a minus in the setting's own section reaches below zero (``values_signed``), a stepping key
printed with the whole word its action shortens ("TRANSPOSE +" for ``trans_up``) is found
(``labels_abbrev``), the held part of a legend line names its on/off setting (``held_parts``)
and a push that starts is the start when only a stop key is named (``legend_starts``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.values import UNIT
from apbot.read.values_signed import signed_spans

# a keyboard whose pitch shift is set with two keys printed in full
KEYBOARD = """
Notara K-61 keyboard

  Keys: ⏻, SHIFT -, SHIFT +, PITCH -, PITCH +

PITCH

The pitch control moves the whole keyboard up or down in semitones.

  - Press PITCH + to go one semitone up, PITCH - to go one semitone down.
  - The range is -5 to +7 semitones. At the ends the value stops.
"""

# a desk amplifier whose volume knob counts decibels below the maximum
AMPLIFIER = """
Sonnet A-2 desk amplifier

  ⏻ ... power
  VOLUME knob ... turn right for louder, left for softer

VOLUME

Turn the VOLUME knob to set how loud it plays. The display shows it in decibels:

   −60 dB (softest) … −30 dB (normal) … 0 dB (loudest)
"""


def test_a_range_with_a_minus_reaches_below_zero() -> None:
    assert signed_spans("The range is -5 to +7 semitones.", UNIT) == [(-5, 7, "")]
    assert signed_spans("The knob stops at −60 dB and 0 dB.", UNIT) == [(-60, 0, "dB")]
    # two negative ends written from the warmer to the colder, in order
    assert signed_spans("Freezer: -15 to -23 °C", UNIT) == [(-23, -15, "°C")]
    # a dash between two figures is no minus; a span with no minus is the unsigned rules'
    assert signed_spans("Levels 1 – 5", UNIT) == []
    # the room's or the sensor's span is no setting's
    assert signed_spans("Operating temperature -10 to +40 °C", UNIT) == []


def test_a_scale_printed_stop_by_stop_spans_its_ends() -> None:
    said = "−60 dB (softest) … −30 dB (normal) … 0 dB (loudest)"
    assert signed_spans(said, UNIT) == [(-60, 0, "dB")]


def test_a_loudness_in_decibels_is_the_volume_range() -> None:
    model = read_manual(AMPLIFIER, ["press_power", "turn_volume_cw", "turn_volume_ccw"]).model
    volume = model.variables["volume"]
    assert volume.type == "numeric"
    assert volume.ranges is not None and (volume.ranges[0][0], volume.ranges[0][1]) == (-60, 0)
    assert volume.unit == "dB"


def test_a_key_printed_with_the_whole_word_takes_its_sections_range() -> None:
    actions = ["press_power", "press_pit_down", "press_pit_up"]
    model = read_manual(KEYBOARD, actions).model
    assert model.controls and any(c.label == "PITCH +" for c in model.controls)
    ranges = [v.ranges for v in model.variables.values() if v.type == "numeric" and v.ranges]
    assert [(-5, 7, 1)] in [[tuple(r) for r in rs] for rs in ranges]


# a bread slicer whose WIDTH key has a second job for holding, in its legend line
SLICER = """
Cutwell BS-2 bread slicer

   1  ⏻        On / off.
   2  WIDTH    Touch: THIN <-> THICK.   Touch and hold 3 seconds: quiet blade on / off.
   3  GO       Starts slicing.

The quiet blade slices slower and with less noise.
"""

# a juicer started by pushing its knob, with a key that only stops it
JUICER = """
Pressa J-9 juicer

   1  ⏻         On / off.
   2  PROGRAM   Turn: choose the programme. Push: START the juicing.
   3  CANCEL    Stops the juicing at once.

The PROGRAM knob has three positions: SOFT -> CITRUS -> HARD. While the juicer runs, RUN is
shown.
"""


def test_a_held_part_of_a_legend_line_names_its_setting() -> None:
    actions = ["press_power", "press_width", "hold_width", "press_go"]
    model = read_manual(SLICER, actions).model
    held = [s for steps in model.features.values() for s in steps if "hold_width" in s.actions]
    assert held and held[0].variable == "quiet_blade"


def test_a_push_that_starts_is_the_start_when_only_a_stop_key_is_named() -> None:
    actions = ["press_power", "turn_knob_cw", "turn_knob_ccw", "push_knob", "press_cancel"]
    model = read_manual(JUICER, actions).model
    starts = [
        s
        for steps in model.features.values()
        for s in steps
        if "push_knob" in s.actions and s.variable == "running"
    ]
    assert starts
    assert "press_cancel" not in model.variables  # (no toggle named after the stop key)
