"""Piecewise time ranges told piece by piece (values_stepped)."""

from apbot.read.values import Range
from apbot.read.values_stepped import find_stepped_pieces


def test_range_then_steps_of() -> None:
    said = (
        "Press + or - to change it: a) from 0:20 to 2:00 in steps of 20 minutes, "
        "b) from 2:00 to 8:00 in steps of 1 hour."
    )
    assert find_stepped_pieces(said) == [
        Range(1200, 7200, "s", 1200),
        Range(7200, 28800, "s", 3600),
    ]


def test_step_then_range() -> None:
    said = (
        "Turn the knob. The time moves: - in 5-minute steps between 0:05 and 1:00, "
        "- in 15-minute steps between 1:00 and 4:00."
    )
    assert find_stepped_pieces(said) == [Range(300, 3600, "s", 300), Range(3600, 14400, "s", 900)]
