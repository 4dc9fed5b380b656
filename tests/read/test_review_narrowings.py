"""Rules of the 6 December evening, narrowed after a review found them misreading ordinary
manuals (each case written for these tests, in the style real manuals use)."""

from __future__ import annotations

from apbot.read.labels import _printed_after_noun
from apbot.read.position_charts import _POSITION_HEAD
from apbot.read.reader import read_manual
from apbot.read.shown import shown_words
from apbot.read.symbol_lamps import symbol_lamp
from apbot.read.text import parse_manual

FAN = """# Tower fan

## Controls
- ⏻ power key
- SPEED key: LOW, MID, HIGH
- OSC key: oscillation on or off

## Using the fan
1. Press ⏻. The fan starts at LOW speed.
2. Press SPEED to change the speed.
3. Press OSC to start or stop the oscillation.

The SPEED and OSC keys work only while the fan is running. Press ⏻ again to stop the fan.
"""


def test_a_power_key_whose_other_keys_wait_for_it_keeps_its_guard() -> None:
    """ "Press ⏻. The fan starts" makes no start/stop of the power key when the manual says
    the other keys work only while the fan runs: they wait for the power, as its guard says."""
    model = read_manual(FAN, ["press_power", "press_speed", "press_osc"]).model
    assert "power" in model.variables
    assert any(g.when.get("power") == "off" for g in model.guards)


def test_a_number_after_a_key_name_is_no_printing_of_it() -> None:
    manual = parse_manual("Hold the timer button 3 seconds to clear the timer.\n")
    assert _printed_after_noun(manual, ["timer"]) is None
    manual = parse_manual("Press the power button 2 times to reset.\n")
    assert _printed_after_noun(manual, ["power"]) is None


def test_a_printing_in_capitals_after_the_noun_is_still_read() -> None:
    manual = parse_manual("Set the main switch I / O at the back to I.\n")
    assert _printed_after_noun(manual, ["main"]) == ("I / O", 1)


def test_a_dash_or_equals_sign_after_a_symbol_is_no_glyph() -> None:
    assert shown_words("The lock symbol – the panel is locked.") == ["LOCK"]
    units = parse_manual("Heat indicator = heating.\n").units
    assert symbol_lamp(units, "Heat") is None


def test_a_real_glyph_after_a_symbol_is_still_read() -> None:
    assert shown_words("When brushing, the brushing symbol ≋ lights.") == ["≋"]


def test_only_a_position_column_keys_a_position_chart() -> None:
    assert _POSITION_HEAD.match("Position")
    assert not _POSITION_HEAD.match("Setting")
    assert not _POSITION_HEAD.match("No.")
