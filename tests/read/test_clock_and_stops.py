"""A 12-hour clock is read only from a sentence about the clock; a knob's end stop only from
its own ends (not "the end of the heating period")."""

import pytest

from apbot.read import read_manual
from apbot.read.clock_format import twelve_hour_clock
from apbot.read.text import parse_manual


@pytest.mark.parametrize(
    ("said", "twelve"),
    [
        # a mode that holds food for twelve hours is no clock
        ("The Stay Warm mode holds the soup hot for up to 12 hours after cooking.", False),
        # a finish time written in am/pm is an example, not the clock's format
        ("Use the delay timer so the oats are ready at 6 a.m. when you get up.", False),
        ("Program it tonight and breakfast is done by 7:15 am.", False),
        # particulate matter, not the afternoon
        ("The display shows the PM 2.5 level of the room air.", False),
        ("The sensor reads PM 2.5 and PM 10 particles in the air.", False),
        # the clock's own format
        ("The clock uses the 12-hour format (AM/PM).", True),
        ("The clock runs from 1:00 to 12:59 and shows PM after noon.", True),
        ("Time of day is shown in 12-hour format.", True),
    ],
)
def test_only_a_sentence_about_the_clock_makes_it_a_twelve_hour_clock(
    said: str, twelve: bool
) -> None:
    assert twelve_hour_clock(parse_manual(f"# T\n\n{said}\n").units) is twelve


def test_a_warm_mode_of_twelve_hours_leaves_the_clock_at_twenty_four_hours() -> None:
    manual = (
        "CONTROLS\n\nPress CLOCK, then HOUR and MIN, to set the time of day.\n\n"
        "STAY WARM\n\nOnce the porridge is done the Stay Warm mode holds it for up to 12 hours.\n"
    )
    model = read_manual(manual, ["press_clock", "press_hour", "press_min", "press_stay_warm"]).model
    clock = next(f for f in model.features.values() if f[0].actions == ["press_clock"])
    assert model.variables[clock[1].variable].ranges[0][0] == "00:00:00"


def _heater(said: str) -> bool | None:
    manual = (
        "CONTROLS\n\nHEAT knob   Main switch and heat setting.\nFAN         Fan on/off.\n\n"
        f"OPERATION\n\nThe knob has five positions. {said}\n\n"
        "     OFF  ·  LOW  ·  MID  ·  HIGH  ·  MAX\n\nTurn the knob away from OFF to switch on.\n"
    )
    model = read_manual(manual, ["turn_knob_cw", "turn_knob_ccw", "press_fan"]).model
    return model.variables["knob"].wrap


def test_stopping_at_the_end_of_a_period_is_no_end_stop_of_the_knob() -> None:
    said = "It turns the element off and stops at the end of the warming cycle."
    assert _heater(said) is not False


def test_a_knob_that_turns_and_stops_at_the_end_still_clamps() -> None:
    assert _heater("It turns up to MAX and stops at the end.") is False
    assert _heater("It turns up to MAX and stops at the ends, with a click.") is False
