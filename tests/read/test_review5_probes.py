"""Rules a second review found firing on ordinary text, each pinned on a small manual of our
own: a setting key whose legend ends by confirming is no bare OK key, ..."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.values import find_ranges

DIGITS = [f"press_{d}" for d in range(10)]

# a countertop oven whose TIMER key is typed on and pressed again to confirm
OVEN_TIMER = """
CONTROL PANEL

POWER  | Switches the oven on or off.
TIMER  | Sets the cooking time, 1 to 90 minutes: type it on the number keys, \
then press TIMER again to confirm the entry.
0 - 9  | Number keys.
START  | Starts cooking.
"""


def test_a_setting_key_whose_legend_ends_by_confirming_is_not_a_bare_ok_key() -> None:
    model = read_manual(OVEN_TIMER, ["press_power", "press_timer", "press_start", *DIGITS]).model
    typed = [
        step.variable
        for steps in model.features.values()
        for step in steps
        if "press_6" in step.actions and step.variable
    ]
    assert typed and all(model.variables[v].label.upper() == "TIMER" for v in typed)


# an air fryer whose DISPLAY key only changes what the display shows while it counts down
FRYER_DISPLAY = """
CONTROL PANEL

POWER   | Switches the fryer on or off.
+ / −   | Raise or lower the cooking time, 1 to 60 minutes.
TEMP    | Picks the temperature: 160, 180 or 200 °C.
DISPLAY | While the fryer counts down, press to switch between the time and the temperature \
on the display.
MODE    | Alternates the auto-mode between the time and the temperature for 1-2 seconds.
START   | Starts frying.
"""
FRYER_ACTIONS = ["press_power", "press_plus", "press_minus", "press_temp", "press_display"]


def test_a_key_that_only_switches_the_display_does_not_switch_the_plus_minus_pair() -> None:
    model = read_manual(FRYER_DISPLAY, [*FRYER_ACTIONS, "press_mode", "press_start"]).model
    for steps in model.features.values():
        pressed = {a for s in steps for a in s.actions}
        assert not ({"press_display", "press_mode"} & pressed and "press_plus" in pressed), steps


def test_a_top_of_24_00_is_a_whole_day_not_24_minutes() -> None:
    assert [r.high for r in find_ranges("The start can be put off by up to 24:00.")] == [86400]
    # a figure no clock shows is still minutes and seconds
    assert [r.high for r in find_ranges("The timer runs up to 30:00.")] == [1800]
    assert [r.high for r in find_ranges("The timer runs up to 24:30.")] == [1470]


def test_a_twelve_hour_clock_top_keeps_its_one_o_clock_bottom() -> None:
    found = find_ranges("The clock can be set up to 12:59.")
    assert [(r.low, r.high) for r in found] == [(3600, 46740)]


# a microwave whose SELECT dial picks a programme; a sentence after the kitchen timer's press
# says the display turns off, and says nothing of the dial
MICRO = """
CONTROL PANEL

SELECT        | Turn to pick the programme: POPCORN, PIZZA, SOUP or VEGETABLES.
KITCHEN TIMER | Counts down 1 to 60 minutes without heating.
START         | Starts cooking.

KITCHEN TIMER

After KITCHEN TIMER has been pressed, {said}
"""
MICRO_ACTIONS = ["turn_select_cw", "turn_select_ccw", "press_kitchen_timer", "press_start"]


def _timer_turns_dial(said: str) -> bool:
    model = read_manual(MICRO.format(said=said), MICRO_ACTIONS).model
    return any(
        {"press_kitchen_timer", "turn_select_cw"} <= {a for s in steps for a in s.actions}
        for steps in model.features.values()
    )


def test_a_dial_is_handed_a_key_s_setting_only_when_the_sentence_turns_that_dial() -> None:
    assert not _timer_turns_dial("the display will turn off when the time is up.")
    assert _timer_turns_dial("turning the SELECT dial sets the minutes.")


# a sandwich toaster whose chart leaves WAFFLE out and has a REHEAT column that is no shade
TOASTER = """KEYS
FOOD      Press to choose the food: TOAST, BAGEL, WAFFLE, CRUMPET.
SHADE     Press to change the browning: LIGHT, MEDIUM, DARK.
START     Starts toasting.

FOOD AND SHADE CHART

✪ used when the food is chosen (standard)      ✦ can be chosen      – not offered

  Food        LIGHT     MEDIUM     DARK     REHEAT
  ------------------------------------------------------
  TOAST       ✦         ✪          ✦        ✦
  BAGEL       –         ✪          ✦        ✦
  CRUMPET     –         –          –        ✦

Press FOOD, then SHADE until the browning you want shows, then START.
"""


def test_a_chart_of_marks_keeps_left_out_programmes_and_only_the_setting_s_values() -> None:
    model = read_manual(TOASTER, ["press_food", "press_shade", "press_start"]).model
    name = next(n for n in model.variables if "shade" in n)
    cases = model.variables[name].model_dump(mode="json")["cases"]
    assert cases and cases["toast"]["values"] == ["light", "medium", "dark"], cases
    assert cases["bagel"]["values"] == ["medium", "dark"], cases
    # left out of the chart: the whole list; a row of dashes (bar a non-shade column): none
    assert cases["waffle"]["values"] == ["light", "medium", "dark"], cases
    assert "crumpet" not in cases, cases
