"""Rules of the set25b session, each on a small manual of our own words: a legend whose items are
led by lettered callouts, "(c) …" or "[B] ▲ / [C] ▼ …", is read item by item
(``text_callouts``); two numbers printed beside a switch's name, "ZONE 1/2", are its positions
(``printed_pairs.printed_pair``); a list of values each led by the icon the display lights is of
the names, shown by their icons (``printed_pairs.icon_led``); a step said as a press's purpose
or a click's effect (``step_phrases``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.text import parse_manual
from apbot.read.value_steps import find_step

# a two-zone fan heater remote (our own words)
HEATER = """
Warmly FH-2 fan heater

 PANEL

   (a) Zone icon: ① hall / ② bedroom
   (b) Sound icon: ♫ chime · ☼ birds · ≈ waves
   (c) KEY - keys locked
   (d) Heat 1-30 for the zone shown
   [A] S - next sound
   [B] ▲ / [C] ▼ - heat up / down
   [D] ⏻ - hold 2 s: heater on / off
   [E] ZONE 1/2 slide switch

 SOUNDS

 Press S to step through the sounds:

      ♫ chime  ->  ☼ birds  ->  ≈ waves  ->  ♫ chime ...

 HEAT

 Press ▲ to raise the heat by 1, ▼ to lower it by 1. The heat stops at 1 and at 30.
"""
ACTIONS = ["hold_power", "slide_zone", "press_s", "press_up", "press_down"]


def test_lettered_legend_items_are_units_of_their_own() -> None:
    texts = [u.text for u in parse_manual(HEATER).units]
    assert "Heat 1-30 for the zone shown" in texts  # not run on into the keys' items
    assert "▲ / ▼ - heat up / down" in texts  # the second callout gone from between the keys
    assert "ZONE 1/2 slide switch" in texts


def test_a_lone_callout_in_prose_is_no_item() -> None:
    text = "Fit the grille first\n(a) and then the filter, which clicks into place.\n"
    texts = [u.text for u in parse_manual(text).units]
    assert any(t.startswith("Fit the grille first (a) and then") for t in texts)


def test_two_numbers_printed_beside_a_switch_are_its_positions() -> None:
    model = read_manual(HEATER, ACTIONS).model
    zone = model.variables["zone"]  # (without the rule: two numbers, a range's ends, dropped)
    assert getattr(zone, "values", None) == ["1", "2"]


def test_values_led_by_icons_are_named_in_words_and_shown_by_icons() -> None:
    model = read_manual(HEATER, ACTIONS).model
    sound = next(v for v in model.variables.values() if "birds" in getattr(v, "values", []))
    assert list(sound.values or []) == ["chime", "birds", "waves"]
    assert sound.show == {"chime": "♫", "birds": "☼", "waves": "≈"}


def test_a_step_said_as_what_a_press_or_click_does() -> None:
    assert find_step("Press ▲ to raise the heat by 1, ▼ to lower it by 1.") == (1.0, "")
    assert find_step("Each click changes the temperature by 5 °C.") == (5.0, "°C")
    assert find_step("Hold ▲ to raise the heat by 10.") is None  # a hold's fast steps
    # a count of something else is no size: "by one lamp (200 rpm)", "by one step"
    assert find_step("Each press lowers the speed by one lamp (400 rpm).") is None
    assert find_step("Each press moves the target by one step.") is None


# a three-way glue gun (our own words): a mode key, a heat knob with a range per mode
GLUE = """
Stickwell GG-3 glue gun

 PANEL

   ( LOW ) ( HIGH ) ( SPRAY )      (HEAT) ②      [MODE] ③
   ①  Mode lamps - one is lit: LOW (craft), HIGH (wood), SPRAY (fabric)
   ②  HEAT knob - nozzle temperature
   ③  MODE key - next mode

 MODES

 Press MODE to step LOW → HIGH → SPRAY → LOW. Each time you change the mode, the heat is set
 to that mode's starting value:

     LOW 120 °C     HIGH 180 °C     SPRAY 150 °C

 HEAT

 Turn the HEAT knob. Each click changes the heat by 5 °C. The knob stops at the end of the
 mode's range:

     LOW     100 - 140 °C
     HIGH    150 - 200 °C
     SPRAY   130 - 170 °C
"""
GLUE_ACTIONS = ["press_mode", "turn_heat_cw", "turn_heat_ccw"]


def test_a_range_per_choice_printed_a_line_each() -> None:
    model = read_manual(GLUE, GLUE_ACTIONS).model
    heat = model.variables["heat"]  # (not LOW / HIGH / SPRAY, the mode lamps drawn beside it)
    assert heat.depends_on == "mode"
    cases = {k: (c.ranges, c.initial) for k, c in (heat.cases or {}).items()}
    assert cases == {
        "low": ([(100, 140, 5)], 120),
        "high": ([(150, 200, 5)], 180),
        "spray": ([(130, 170, 5)], 150),
    }


# a two-mode massage gun (our own words): the DIAL does a different job per mode
MASSAGE = """
Kneadr MG-2 massage gun

 CONTROLS

 Press MODE to step PULSE → STEADY → RAMP → PULSE.

 THE DIAL: BEAT RATE / RAMP OFFSET

 The DIAL does another job in each mode. Turn it one click at a time.

 | Mode   | DIAL sets     | Range      | Starts at | Notes                 |
 |--------|---------------|------------|-----------|-----------------------|
 | PULSE  | Beat rate     | 1 ... 9    | 4         | beats per second      |
 | STEADY | -- (nothing)  | -          | -         | the dial does nothing |
 | RAMP   | Ramp offset   | -3 ... +3  | 0         | minus: slower ramp    |
"""
MASSAGE_ACTIONS = ["press_mode", "turn_dial_cw", "turn_dial_ccw"]


def test_a_range_column_per_choice_makes_an_amount_not_names() -> None:
    model = read_manual(MASSAGE, MASSAGE_ACTIONS).model
    dial = model.variables["dial"]  # (without the rule: "beat rate", "ramp offset", names)
    assert dial.type == "numeric" and dial.depends_on == "mode"
    cases = {k: (c.ranges, c.initial) for k, c in (dial.cases or {}).items()}
    assert cases == {"pulse": ([(1, 9, 1)], 4), "ramp": ([(-3, 3, 1)], 0)}


def test_a_hold_is_not_read_from_the_next_keys_legend_row() -> None:
    model = read_manual(HEATER, [*ACTIONS, "hold_up"]).model
    # "[D] ⏻ - hold 2 s: heater on / off" is the power key's row, not what holding ▲ does
    assert not any(
        "hold_up" in (step.actions or []) and getattr(step, "effect", None) == "toggle"
        for steps in model.features.values()
        for step in steps
    )


def test_small_numbers_shown_circled() -> None:
    model = read_manual(HEATER, ACTIONS).model
    zone = model.variables["zone"]
    assert zone.show == {"1": "①", "2": "②"}
