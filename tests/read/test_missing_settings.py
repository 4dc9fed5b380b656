"""Settings the reader missed because of a manual's structure (round 8), each on a small manual
written in our own words the way a commercial manual reads once converted to text."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a fan heater whose table of contents lists the special functions by their names
HEATER = """BRISKA FH-20 fan heater

Contents
   Safety ................................................ 2
   The keys .............................................. 3
   Heat levels ........................................... 4
   Extra functions: FROST, NIGHT, TURBO HEAT, TURBO FAN ..... 5
   Cleaning .............................................. 7

Heat levels
Press HEAT to go from level 1 to level 2 and 3.

Turbo
TURBO HEAT (touch TURBO briefly) heats at full power for 30 minutes. Touch TURBO again to
switch it off. The key sound can be switched on or off with SOUND.
"""
ACTIONS = ["press_heat", "press_turbo", "press_sound"]


def test_contents_lines_are_no_text() -> None:
    units = parse_manual(HEATER).units
    assert not any("FROST" in u.text or "Cleaning" in u.text for u in units)
    assert any("TURBO HEAT" in u.text for u in units)


def test_a_contents_title_lends_a_key_no_values() -> None:
    model = read_manual(HEATER, ACTIONS).model  # not frost, night, turbo heat, turbo fan
    assert model.variables["turbo"].values == ["off", "on"]


def test_dot_leaders_of_a_specification_list_stay() -> None:
    specs = (
        "Specifications\n\nPower ........ 2000 W\nTimer ........ 1 - 12 h\nWeight ....... 3 kg\n"
    )
    text = " ".join(u.text for u in parse_manual(specs).units)
    assert "2000 W" in text and "1 - 12 h" in text


def test_a_contents_in_two_columns_is_dropped_too() -> None:
    text = (
        "CONTENTS\n"
        "Safety ............... 2     Programmes .......... 5\n"
        "The panel ............ 3     Cleaning ............ 8\n"
        "Specifications ....... 4     Guarantee ........... 10\n\n"
        "Press SPIN to choose 400, 800 or 1200 rpm.\n"
    )
    texts = [u.text for u in parse_manual(text).units]
    assert not any("Guarantee" in t or "Programmes" in t for t in texts)
    assert any("SPIN" in t for t in texts)
