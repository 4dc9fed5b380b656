"""Rules found on the styled (commercial-style) manuals, each on a small manual of our own
written the way a converted commercial manual reads."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.model.schema import DiscreteVariable
from apbot.read import read_manual
from apbot.read.values import EACH_PRESS_RE

# an oven with one push-turn dial: it picks the function, and after TEMP or TIME it sets those
OVEN = """CONTROLS

                 ┌──────────────────────┐
                 │   GRILL  200°C  0:20 │
                 └──────────────────────┘
       ON/OFF                          LIGHT
       TEMP          ( MODE )          TIME
                   START/STOP

 Control        Description
 ON/OFF         Switches the oven on or off.
 MODE dial      Turn to choose a function, or after TEMP or TIME to change that setting.
                Push the dial to go back to choosing a function.
 TEMP           Lets the dial change the temperature.
 TIME           Lets the dial change the cooking time.
 LIGHT          Switches the oven light on or off.
 START/STOP     Starts or stops cooking.

Functions are printed round the MODE dial, clockwise:

   GRILL → FAN → PIZZA → DEFROST → (GRILL …)

USING THE OVEN

1. Press ON/OFF.
2. Turn the MODE dial to the function.
3. Press TEMP and turn the dial to set the temperature, 50 °C – 250 °C.
4. Press TIME and turn the dial to set the cooking time, 1 – 90 min.
5. Press START/STOP.

Temperature: every click of the dial changes the temperature by 10 °C.
Time: every click changes the time by 1 minute.
"""
ACTIONS = ["press_on_off", "turn_cw", "turn_ccw", "press_dial", "press_temp", "press_time"]
ACTIONS += ["press_light", "press_start_stop"]


def _steps(model, variable: str) -> list[list[list[str]]]:  # type: ignore[no-untyped-def]
    return [
        [list(step.actions) for step in steps]
        for steps in model.features.values()
        if steps and steps[-1].variable == variable
    ]


def test_a_key_then_the_dials_clicks_set_its_amount() -> None:
    model = read_manual(OVEN, ACTIONS).model
    temp = next(n for n in model.variables if n.startswith("temp"))
    time = next(n for n in model.variables if "time" in n)
    # "every click (of the dial)" is the dial's turn, not each press of TEMP or TIME
    assert _steps(model, temp) == [[["press_temp"], ["turn_cw", "turn_ccw"]]]
    assert _steps(model, time) == [[["press_time"], ["turn_cw", "turn_ccw"]]]


def test_a_push_turn_dials_ring_of_names_is_what_its_turns_pick() -> None:
    model = read_manual(OVEN, ACTIONS).model
    picked = [
        n
        for n, v in model.variables.items()
        if isinstance(v, DiscreteVariable) and "pizza" in v.values
    ]
    assert len(picked) == 1
    assert _steps(model, picked[0]) == [[["turn_cw", "turn_ccw"]]]


def test_the_next_keys_name_on_a_panel_drawing_is_no_list_of_values() -> None:
    model = read_manual(OVEN, ACTIONS).model
    time = next(n for n in model.variables if "time" in n)
    assert not isinstance(model.variables[time], DiscreteVariable)


# a washer's numbered panel legend: three knobs, each paragraph saying where it stops
WASHER = """  ①          ②         ③         ④
  CYCLE      TEMP      SPIN      START

① CYCLE selector — chooses the wash cycle. The knob turns in both
   directions all the way round, without a stop. Clockwise it gives the order
   of the cycle table.
② TEMP knob — positions, from left to right:
       COLD (cold water)   30   40   60
   The knob stops at COLD and at 60. Clockwise = warmer.
③ SPIN knob — positions, from left to right:
       0 (no spin)   600   800   1000
   Clockwise = faster. The knob stops at both ends. ④ START — starts the cycle.

CYCLE TABLE

Cycle        Temperature     Spin
Cotton       30 – 60 °C      1000
Synthetic    30 – 40 °C      800
Wool         COLD – 30 °C    600
"""
WASHER_ACTIONS = ["turn_cycle_cw", "turn_cycle_ccw", "turn_temp_cw", "turn_temp_ccw"]
WASHER_ACTIONS += ["turn_spin_cw", "turn_spin_ccw", "press_start"]


def test_a_marks_gloss_does_not_break_the_row_of_marks() -> None:
    model = read_manual(WASHER, WASHER_ACTIONS).model
    assert list(all_values(model.variables["temp"])) == ["cold", "30", "40", "60"]
    assert [float(v) for v in all_values(model.variables["spin"])] == [0, 600, 800, 1000]


def test_a_knob_stops_where_its_own_paragraph_says_not_where_the_one_before_goes_round() -> None:
    model = read_manual(WASHER, WASHER_ACTIONS).model
    assert model.variables["cycle"].wrap is True
    assert model.variables["temp"].wrap is False
    assert model.variables["spin"].wrap is False


def test_a_keys_word_with_on_that_the_display_shows_is_the_sign_it_is_on() -> None:
    manual = (
        "Keys\n\n  POWER        switches the unit on and off\n"
        "  NIGHT MODE   switches night mode on / off\n\n"
        "Display\n\n  NIGHT ON     night mode is switched on\n  Lc           keys locked\n"
    )
    model = read_manual(manual, ["press_power", "press_night_mode"]).model
    night = next(v for n, v in model.variables.items() if n.startswith("night"))
    assert isinstance(night.show, dict) and night.show.get("on") == "NIGHT ON"


def test_what_the_next_sentence_says_of_it_is_said_of_the_knob() -> None:
    manual = (
        "CONTROLS\n\nHEAT knob   Main switch and heat setting.\nFAN         Fan on/off.\n\n"
        "OPERATION\n\nThe knob has five positions. It clicks at each one and stops at both "
        "ends.\n\n     OFF  ·  LOW  ·  MID  ·  HIGH  ·  MAX\n\nTurn the knob away from OFF "
        "to switch on.\n"
    )
    model = read_manual(manual, ["turn_knob_cw", "turn_knob_ccw", "press_fan"]).model
    assert model.variables["knob"].wrap is False


def test_an_it_sentence_joins_the_knob_only_when_it_speaks_of_the_knobs_turns_or_ends() -> None:
    manual = (
        "CONTROLS\n\nHEAT knob   Main switch and heat setting.\nFAN         Fan on/off.\n\n"
        "OPERATION\n\nThe knob has five positions. It stops at the end of the heating period "
        "and gives a beep.\n\n     OFF  ·  LOW  ·  MID  ·  HIGH  ·  MAX\n\nTurn the knob away "
        "from OFF to switch on. The knob turns all the way round, from MAX on to OFF.\n"
    )
    model = read_manual(manual, ["turn_knob_cw", "turn_knob_ccw", "press_fan"]).model
    assert model.variables["knob"].wrap is True  # the heating stops, not the knob


# a fan heater whose timer is a knob you press, not turn
HEATER = """CONTROLS

 POWER         Switches the fan heater on or off.
 TIMER knob    Every push of the timer knob adds an hour before the heater turns itself off (1–8 h).

1. Press POWER.
2. Press the TIMER knob until the hours you want are set.
"""


def test_each_press_of_a_knob_is_a_press_only_a_dials_click_is_a_turn() -> None:
    reading = read_manual(HEATER, ["press_power", "press_timer"])
    read = {n.subject: n for n in reading.report.notes if not n.guess}
    assert read["features.set_timer"].line == 4  # read from the legend, not guessed
    assert EACH_PRESS_RE.search("Each press of the timer knob adds one hour")
    assert not EACH_PRESS_RE.search("every click of the dial changes the temperature")
    assert EACH_PRESS_RE.search("every click changes the time by 1 minute")
