"""Rules of the values31 session, each on a small manual of our own words: a setting whose
range the manual gives nowhere the usual patterns look takes the span its own section states
("The range is 415 Hz to 466 Hz", "At 1, … nothing more; at 12, …", "stops at 0 and at 8",
a clock span "0:05 to 4:00"), instead of a guessed 0–10 (``values_stated``)."""

from __future__ import annotations

from apbot.model.schema import NumericVariable
from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.values_stated import stated_halts, stated_in_section, stated_span

# a practice amplifier: a reference tone, a speaker level, a hum filter and a sleep timer
AMP = """
Corvo PA-2 practice amplifier

KEYS

  TONE – the reference tone for tuning
  LEVEL – the speaker level
  NOTCH – the hum filter
  NAP – the sleep timer
  ▲ ▼ – change the value shown

REFERENCE TONE

The tone sounds the note A.
 1. Press TONE. The display shows the tone, e.g. A 440.
 2. Press ▲ or ▼ to move it by 1 Hz. The range is 415 Hz to 466 Hz; the value stops at
    either end.

SPEAKER LEVEL

Each press of LEVEL raises the level by one. At 1, ▼ does nothing more; at 12, ▲ does
nothing more.

HUM FILTER

Press NOTCH, then ▲ or ▼. The filter depth stops at 0 and at 8.

SLEEP

 1. Press NAP. The display shows the time left, e.g. 0:30.
 2. Press ▲ or ▼ to change it by five minutes. The range is 0:05 to 4:00 (hours:minutes).
"""

AMP_KEYS = ["press_tone", "press_level", "press_notch", "press_nap", "press_up", "press_down"]


def _numeric(name: str) -> NumericVariable:
    var = read_manual(AMP, AMP_KEYS).model.variables[name]
    assert isinstance(var, NumericVariable)
    return var


def test_a_span_with_its_unit_on_both_ends() -> None:
    assert stated_span("The range is 415 Hz to 466 Hz; the value stops at either end.") == (
        415,
        466,
        "Hz",
    )
    tone = _numeric("tone")
    assert (tone.ranges[0][0], tone.ranges[0][1]) == (415, 466)  # not a guessed 0–10
    assert not tone.wrap  # "the value stops at either end"


def test_the_two_places_the_keys_stop() -> None:
    assert stated_span("At 1, ▼ does nothing more; at 12, ▲ does nothing more.") == (1, 12, "")
    level = _numeric("level")
    assert (level.ranges[0][0], level.ranges[0][1]) == (1, 12)  # not a guessed 0–10
    assert stated_span("The filter depth stops at 0 and at 8.") == (0, 8, "")


def test_a_clock_span_after_the_key_is_a_time() -> None:
    units = parse_manual(AMP).units
    found = stated_in_section(units, "nap", "NAP")  # after "Press NAP.", in seconds
    assert found is not None
    assert (found[0].low, found[0].high, found[0].unit) == (5 * 60, 4 * 3600, "s")


def test_where_the_appliance_works_is_no_span() -> None:
    assert stated_span("The operating range is 5 to 40 °C.") is None
    assert stated_span("The range is level 1 (softest) to level 5.") == (1, 5, "")
    assert stated_halts("It stops at 20 and at 90 (no wrap-around).")
    assert not stated_halts("After 9 it starts again at 1.")
