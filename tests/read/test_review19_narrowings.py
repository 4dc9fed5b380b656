"""Misfires of set18's reader rules on manuals of other appliances, each narrowed: keys said to
"set the temperature" step it (``value_keys._named_keys``), a lamp word is only a place when the
panel's word follows it in capitals (``code_glosses``), and "only while … runs" of another
clause is not said of a dial's turn (``turn_refusals``), nor "starts" of a RUN key
(``roles_running``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.code_glosses import _name

# a water heater whose UP and DOWN keys step the temperature
HEATER = """
Warmio WH-2 water heater

  Keys: POWER, UP, DOWN, BOOST

Press POWER to switch on. Press UP or DOWN to set the temperature. The temperature can be set
from 30 to 75 °C in steps of 5 °C; the display shows the temperature.
Press BOOST to heat at full power.
"""

# an alarm clock whose HOUR and MIN keys each step their own number
CLOCK = """
Dawnly AC-1 alarm clock

  Keys: POWER, HOUR, MIN, ALARM

Press POWER to switch on. Press HOUR or MIN to set the clock. Each press of HOUR adds one hour
(0 to 23); each press of MIN adds one minute (0 to 59). The display shows the time.
Press ALARM to turn the alarm on or off.
"""

# a fan heater whose manual says, in another clause, what glows only while the fan runs
FAN_HEATER = """
Toastie FH-3 fan heater

  Keys: POWER, START/STOP, HEAT dial (turn right = warmer, turn left = cooler)

Press POWER to switch on. Press START/STOP to start or stop the fan.
The heat goes from 1 to 9. Turn toward warmer to raise the heat; the element glows only while
the fan runs.
"""


def test_keys_said_to_set_a_number_still_step_it() -> None:
    actions = ["press_power", "press_up", "press_down", "press_boost"]
    temperature = read_manual(HEATER, actions).model.variables["temperature"]
    assert temperature.type == "numeric"  # (not a choice of "up" or "down")
    assert [tuple(r) for r in temperature.ranges] == [(30, 75, 5)]


def test_keys_said_to_set_the_clock_keep_their_own_numbers() -> None:
    model = read_manual(CLOCK, ["press_power", "press_hour", "press_min", "press_alarm"]).model
    assert "clock" not in model.variables
    assert model.variables["hour"].type == "numeric"
    assert model.variables["min"].type == "numeric"


def test_light_before_a_word_in_small_letters_is_part_of_its_name() -> None:
    # "MIST (light mist)": a lighter mist, not the lamp that shows MIST
    assert _name("light mist", "mist", set()) == "light mist"
    assert _name("lamp PEDAL", "pedal", set()) is None


def test_only_while_running_said_of_another_clause_guards_no_turn() -> None:
    actions = ["press_power", "press_start_stop", "turn_warmer", "turn_cooler"]
    model = read_manual(FAN_HEATER, actions).model
    assert not [g for g in model.guards if g.when == {"running": "off"}]


# an air purifier whose RUN key shows the filter's hours; the count, not RUN, starts again
PURIFIER = """
Breezo AP-7 air purifier

  Keys: POWER, FAN, RUN, RESET

Press POWER to switch on. Press FAN to choose the fan speed: LOW, MED or HIGH.
Press RUN to show the hours the filter has run; the count starts again from 0 after RESET.
Hold RESET for 3 seconds after changing the filter.
"""


def test_run_is_no_start_key_where_another_clause_starts() -> None:
    model = read_manual(PURIFIER, ["press_power", "press_fan", "press_run", "press_reset"]).model
    assert "running" not in model.variables
