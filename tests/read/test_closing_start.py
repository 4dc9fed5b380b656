"""A keypad entry whose procedure ends by pressing START that only confirms keeps that START as
its last step (a clock, an egg timer that heats nothing); a START that runs the appliance (a
defrost procedure) stays the start feature's."""

from __future__ import annotations

from apbot.read import read_manual

DIGITS = [f"press_{d}" for d in range(10)]
ACTIONS = [*DIGITS, "press_timer", "press_clock", "press_thaw", "press_start", "press_stop"]

OVEN = """\
# Compact oven OV-3

## Keys

- **TIMER**: egg timer, the oven stays cold (no heating).
- **CLOCK**: time of day.
- **THAW**: thawing for a time you type.
- **START**: go.
- **STOP**: stop and clear.

## Time of day

1. Press **CLOCK**.
2. Type the hours and minutes on the number keys.
3. Press **START** to store it.

## Thawing

1. Press **THAW**.
2. Type the thawing time in minutes and seconds.
3. Press **START**.

## Egg timer

Press **TIMER**, enter the minutes with the number keys, press **START**. It rings at zero.
"""


def _steps(feature: str) -> list[list[str]]:
    model = read_manual(OVEN, ACTIONS).model
    return [s.actions for s in model.features[feature]]


def test_a_timer_that_heats_nothing_ends_with_its_confirming_start() -> None:
    steps = _steps("set_timer")
    assert steps[0] == ["press_timer"] and steps[-1] == ["press_start"], steps


def test_the_clock_ends_with_the_start_that_stores_it() -> None:
    steps = _steps("set_clock")
    assert steps[-1] == ["press_start"], steps


def test_a_start_that_runs_the_thawing_stays_the_start_features() -> None:
    steps = _steps("set_thaw")
    assert ["press_start"] not in steps, steps


def test_a_procedure_pressing_another_key_before_start_gets_no_closing_start() -> None:
    text = OVEN.replace(
        "2. Type the hours and minutes on the number keys.",
        "2. Type the hours and minutes on the number keys.\n3. Press **TIMER**.",
    ).replace("3. Press **START** to store it.", "4. Press **START** to store it.")
    model = read_manual(text, ACTIONS).model
    steps = [s.actions for s in model.features["set_clock"]]
    assert ["press_start"] not in steps, steps
