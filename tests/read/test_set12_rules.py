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


# a juicer: a knob turned for the speed and pushed to start, a pair held together for the lock,
# a key pressed on and "pressed again" off, speed lamps beside a display that prints the figure
JUICER = """
Pressa J-7 slow juicer

Panel

   ⏻          on / off
   PULP - / PULP +   less / more pulp (hold both 3 s: child lock)
   COOL       cool the juice (snowflake lamp)
   SPEED      knob. Turn: speed level. Push: start / stop juicing

   Display texts

     SPEED 2         speed level while the knob is turned
     LOCK            child lock on

Speed
   Turn the SPEED knob to the right for a higher speed (1 – 3). Each click is one level.
   The speed lamps show the level:
   ●○○   1   gentle
   ●●○   2   normal
   ●●●   3   fast

Cooling
   Press COOL: the snowflake lamp lights and the juice is cooled.
   Press again to switch it off. Cooling adds 1 – 2 minutes.

Juicing
   1. Check the settings.
   2. Push the SPEED knob. The juicer starts.
   To stop early, push the SPEED knob again.

Child lock
   Press and hold PULP - and PULP + together for 3 seconds. LOCK appears.
"""
JUICER_ACTIONS = [
    "press_power", "turn_speed_cw", "turn_speed_ccw", "push_speed", "press_pulp_minus",
    "press_pulp_plus", "hold_pulp_both", "press_cool",
]  # fmt: skip


def _step_of(model, action: str):  # type: ignore[no-untyped-def]
    return next(s for ss in model.features.values() for s in ss if action in s.actions)


def test_a_pair_held_both_is_the_child_lock() -> None:
    model = read_manual(JUICER, JUICER_ACTIONS).model
    assert any(g.name == "child lock" and g.only == ["hold_pulp_both"] for g in model.guards)


def test_a_knob_whose_legend_says_push_start_stop_starts_and_stops() -> None:
    model = read_manual(JUICER, JUICER_ACTIONS).model
    step = _step_of(model, "push_speed")
    assert step.variable == "running" and step.effect == "toggle"


def test_press_again_to_switch_it_off_makes_the_key_a_toggle() -> None:
    model = read_manual(JUICER, JUICER_ACTIONS).model
    step = _step_of(model, "press_cool")
    assert step.effect == "toggle" and model.variables[str(step.variable)].values == ["off", "on"]


def test_lamps_as_bars_give_way_to_a_display_text_with_the_figure() -> None:
    model = read_manual(JUICER, JUICER_ACTIONS).model
    shows = [v.show for v in model.variables.values() if v.label == "SPEED"]
    assert shows and not any(isinstance(s, dict) and "●○○" in s.values() for s in shows)


def test_steps_written_out_are_numbered_steps() -> None:
    text = "Setting the time\n\n  Step 1  Touch SET. The hours flash.\n  Step 2: Touch ▲ or ▼.\n"
    steps = [u.step for u in parse_manual(text).units if u.step is not None]
    assert steps == [1, 2]


# a treadmill: the incline alert's values printed as the display shows them, word and figure
TREADMILL = """
Stridon T-4 treadmill

Keys: ⏻  ALERT  START

Heart-rate alert
  Press ALERT to choose the heart rate above which the console beeps. Each press moves
  one step:

    BPM OFF → BPM 120 → BPM 140 → BPM 160 → BPM OFF ...
"""
TREADMILL_ACTIONS = ["press_power", "press_alert", "press_start"]


def test_values_printed_as_a_display_word_and_a_figure_are_the_figures() -> None:
    model = read_manual(TREADMILL, TREADMILL_ACTIONS).model
    var = next(
        s.variable for ss in model.features.values() for s in ss if s.actions == ["press_alert"]
    )
    spec = model.variables[str(var)]
    assert spec.values == ["off", "120", "140", "160"]
    assert spec.show == {"off": "BPM OFF", "120": "BPM 120", "140": "BPM 140", "160": "BPM 160"}


def test_a_held_toggle_whose_word_marks_off_gets_no_on_word() -> None:
    text = YOGHURT.replace("SOFT appears and the cultures ferment at 36 °C", "SOFT OFF appears")
    model = read_manual(text, YOGHURT_ACTIONS).model
    var = next(
        s.variable for ss in model.features.values() for s in ss if s.actions == ["hold_set"]
    )
    assert model.variables[str(var)].show != {"off": "", "on": "SOFT OFF"}
