"""Set 12 reader rules, each on a small manual in our own words: a key held to switch on and
held to switch off in two sentences is the power; a chart drawn with double-line box
characters is a table."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual

# a hand-held foot warmer: switching on and switching off get a sentence each
WARMER = """
Toasta FW-2 foot warmer

Keys
  ⏻      hold it (see below)
  −  +   heat down / up

Getting started
Press and hold ⏻ for 3 seconds to switch on. The lamps light.
Press and hold ⏻ for 3 seconds to switch off. A short press does nothing.

The heat goes from 1 to 4. Press + for more heat, − for less.
"""
WARMER_ACTIONS = ["hold_power", "press_minus", "press_plus"]

# a grinder's chart drawn with double lines
DOUBLE_BOX = """GRINDA G-5 GUIDE

╔══════════╦══════════════╦════════════╗
║ Setting  ║ Grind        ║ Seconds    ║
╠══════════╬══════════════╬════════════╣
║ FINE     ║ espresso     ║ 20         ║
║ COARSE   ║ press pot    ║ 10         ║
╚══════════╩══════════════╩════════════╝
"""


def test_a_key_held_to_switch_on_and_held_to_switch_off_is_the_power() -> None:
    model = read_manual(WARMER, WARMER_ACTIONS).model
    power = [g for g in model.guards if g.name == "power off"]
    assert power and power[0].only == ["hold_power"]
    step = next(s for steps in model.features.values() for s in steps if "hold_power" in s.actions)
    assert step.variable == "power" and step.effect == "toggle"


def test_a_hold_that_only_switches_on_is_not_the_power() -> None:
    text = WARMER.replace("to switch off", "to reset the heat")
    model = read_manual(text, WARMER_ACTIONS).model
    assert not [g for g in model.guards if g.name == "power off"]


def test_a_double_line_box_is_read_as_a_table() -> None:
    rows = [u.cells for u in parse_manual(DOUBLE_BOX).units if u.cells]
    assert ("FINE", "espresso", "20") in [tuple(r) for r in rows]
