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


# a bottle warmer: the first touch of DELAY only shows the delay, each further touch adds
WARMER_DELAY = """
Tepida BW-3 bottle warmer

Keys: ⏻  MODE  WARM  −  +  DELAY  START

Delayed start
1. Touch DELAY. The delay is shown; this first touch changes nothing.
2. Each further touch adds one hour, up to 8 hours. After 8 hours it returns to 0.
3. Touch START.

Warming time
To change the warming time, touch WARM, then − or +. The time goes from 5 to 30 minutes.
"""
WARMER_DELAY_ACTIONS = [
    "press_power", "press_mode", "press_warm", "press_minus", "press_plus", "press_delay",
    "press_start",
]  # fmt: skip

# a yoghurt maker: holding SET switches a setting the display shows by a word of its own
YOGHURT = """
Cultura YM-2 yoghurt maker

Keys: ⏻  SET  −  +

Fermenting time
Touch SET, then − or + to change the time from 4 to 12 hours.

Gentle mode
Touch and hold SET for 3 seconds: SOFT appears and the cultures ferment at 36 °C. Hold SET
for 3 seconds again to switch gentle mode off.
"""
YOGHURT_ACTIONS = ["press_power", "press_set", "hold_set", "press_minus", "press_plus"]


def test_each_further_touch_of_a_key_steps_its_own_setting() -> None:
    model = read_manual(WARMER_DELAY, WARMER_DELAY_ACTIONS).model
    steps = [s for ss in model.features.values() for s in ss if s.actions == ["press_delay"]]
    assert steps and steps[0].variable == "delay" and steps[0].effect == "next"


def test_a_held_toggle_is_shown_by_the_word_its_hold_sentence_says_appears() -> None:
    model = read_manual(YOGHURT, YOGHURT_ACTIONS).model
    var = next(
        s.variable for ss in model.features.values() for s in ss if s.actions == ["hold_set"]
    )
    assert var is not None
    assert model.variables[var].show == {"off": "", "on": "SOFT"}
