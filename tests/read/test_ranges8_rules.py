"""Values and ranges the read model lacked (round 8), each on a small manual of our own."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.values_wraps import find_wrap

# a terrarium lamp: two example times read as one range, the wrap sentence gives the whole day
TERRARIUM = """KEYS

  ON TIME     choose when the lamp switches on
  OFF TIME    choose when the lamp switches off
  UP / DOWN   move the selected time

LAMP TIMES

 Out of the box the lamp uses 07:00 (on time) and 19:00 (off time).
 The times move in steps of 30 minutes; after 23:30 comes 00:00 again.

 1. Press ON TIME or OFF TIME. The display shows the time.
 2. Press UP or DOWN until the time you want is shown.
"""

TERRARIUM_ACTIONS = ["press_on_time", "press_off_time", "press_up", "press_down"]

# a yoghurt maker: the delay counts up to 12 h, one more press gives 0 (off)
CULTURER = """KEYS

  DELAY    hours until the programme starts

DELAY
 Each press of DELAY adds one hour: 1, 2, 3 ... up to 12 hours.
 One more press after 12 h sets the delay back to 0 (no delay).
"""


def test_a_wrap_sentence_gives_the_ends() -> None:
    found = find_wrap("The times move in steps of 30 minutes; after 23:30 comes 00:00 again.")
    assert found is not None and (found.low, found.high, found.unit) == (0, 84600, "s")
    found = find_wrap("One more press after 12 h sets the delay back to 0 (no delay).")
    assert found is not None and (found.low, found.high, found.unit) == (0, 12, "h")
    found = find_wrap("After 23 h it comes back to 0 h.")
    assert found is not None and (found.low, found.high, found.unit) == (0, 23, "h")
    # a wait, not a wrap: "after about 10 minutes it falls back to 9" names another thing
    assert find_wrap("after about 10 minutes the zone falls back to 9") is None
    assert find_wrap("after MENU 15 the display goes back to MENU 1") is None


def test_a_clock_setting_that_wraps_covers_the_whole_day() -> None:
    model = read_manual(TERRARIUM, TERRARIUM_ACTIONS).model
    spec = model.variables["on_time"].model_dump(mode="json")
    assert spec["ranges"] == [["00:00:00", "23:30:00", 1800]], spec


def test_a_count_that_wraps_to_zero_includes_zero() -> None:
    model = read_manual(CULTURER, ["press_delay"]).model
    spec = model.variables["delay"].model_dump(mode="json")
    assert spec["ranges"][0][0] == 0 and spec["ranges"][-1][1] == 12, spec


# a wine chiller: the settings listed with the middle left out, and where the list starts again
CHILLER = """KEYS

  COLD    one degree colder per touch

COLD
 Each touch of COLD makes the cellar one degree colder, and after the coldest it starts again:

     -2 → -3 → -4 → ... → -9 → -10 → -2 → ...   (°C)
"""

# a fan heater's off-timer: two runs of steps, each shortened with an ellipsis
FAN = """KEYS

  ▲ TIMER   switch-off time in hours

OFF TIMER
 1. Press ▲ TIMER. Up to 6 hours the time goes up by half an hour per press; above 6 hours by
    two hours per press: 1 → 1.5 → 2 → ... → 5.5 → 6 → 8 → 10 → ... → 22 → 24 h
 2. One more press after 24 h sets the timer back to 0 (timer off).
"""


def test_a_list_shortened_with_an_ellipsis_is_filled_in_at_its_step() -> None:
    values = read_manual(CHILLER, ["press_cold"]).model.variables["cold"].model_dump(mode="json")
    assert values["values"] == [str(-n) for n in range(2, 11)], values


def test_two_elided_runs_are_each_filled_at_their_own_step() -> None:
    spec = read_manual(FAN, ["press_timer"]).model.variables["timer"].model_dump(mode="json")
    assert spec["ranges"] == [[0, 1, 1], [1, 6, 0.5], [6, 24, 2]] or spec["ranges"] == [
        [0, 6, 0.5],
        [6, 24, 2],
    ], spec
