"""A time typed on the number keys that the manual says to enter "in minutes and seconds" is
minutes:seconds on the keypad and on the display, to the second — whatever range the reader
guessed for it (a countdown's "12" is twelve seconds, not twelve minutes)."""

from __future__ import annotations

from apbot.model.values import parse_hms
from apbot.read import read_manual
from apbot.read.value_steps import find_step

STEAMER = """Steam Oven SO-4

KEYS
STEAM    Steam cooking.
TIMER    A countdown that does not heat.
0-9      Number keys.
START    Starts the oven or the countdown.

STEAM COOKING
1. Press STEAM.
2. Enter the cooking time in minutes and seconds: 1, 2, 0, 0 gives 12:00.
3. Press START.

COUNTDOWN
1. Press TIMER.
2. Enter the minutes and seconds.
3. Press START. The display counts down.
"""
ACTIONS = ["press_steam", "press_timer", "press_start", *[f"press_{d}" for d in range(10)]]


def test_entering_minutes_and_seconds_is_a_step_of_one_second() -> None:
    assert find_step("Enter the minutes and seconds.") == (1.0, "s")
    assert find_step("Type the thawing time in minutes and seconds, as for COOK.") == (1.0, "s")
    assert find_step("The display shows minutes and seconds.") is None  # shown, not entered


def test_a_countdown_entered_in_minutes_and_seconds_is_typed_to_the_second() -> None:
    model = read_manual(STEAMER, ACTIONS).model
    timers = [
        spec for name, spec in model.variables.items() if spec.type == "time" and "timer" in name
    ]
    assert timers, list(model.variables)
    spec = timers[0]
    assert spec.format == "mm:ss"
    assert any(
        parse_hms(lo) <= 12 <= parse_hms(hi) and int(step) == 1 for lo, hi, step in spec.ranges
    )


def test_minutes_and_seconds_worked_out_after_a_weight_is_keyed_are_no_keyed_time() -> None:
    said = "Enter the weight with the number keys, and the oven works out the minutes and seconds."
    assert find_step(said) is None
    assert find_step("Times are always entered as minutes and seconds.") == (1.0, "s")
