"""A chain of clock values joined by dashes ("0:20 – 0:40 – 1:00 – 1:20") lists the values one
by one: its range runs from the first to the last, in the step between them — not from the first
to the second, as a lone pair "0:20 – 0:40" would."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.values import Range, find_ranges


def test_a_chain_of_clock_values_is_one_stepped_range() -> None:
    assert find_ranges("Each press: 0:20 – 0:40 – 1:00 – 1:20") == [Range(1200, 4800, "s", 1200)]


def test_a_lone_pair_of_clock_values_is_still_a_range() -> None:
    assert find_ranges("from 0:20 – 1:20") == [Range(1200, 4800, "s", None)]


def test_an_unsorted_chain_gives_no_range() -> None:
    assert find_ranges("2:00 – 0:30 – 1:00") == []


def test_a_dial_of_uneven_delays_keeps_every_piece_in_whole_seconds() -> None:
    """10 s read in minutes is 0.166667 min: back in seconds it is 10, so the 10 s – 30 s piece
    between the dial's stops is kept, not dropped as a step that does not fit."""
    model = read_manual(_DOOR, ["turn_autoclose_cw", "turn_autoclose_ccw"]).model
    close = model.variables["autoclose"]
    assert close.ranges == [  # type: ignore[union-attr]
        ("00:00:00", "00:00:10", 10),
        ("00:00:10", "00:00:30", 20),
        ("00:00:30", "00:01:00", 30),
        ("00:01:00", "00:03:00", 120),
    ]


_DOOR = """DOORGUARD D-1 DOOR CLOSER
Instructions

KEYS
   AUTO-CLOSE dial      turn: choose the closing delay

CLOSING DELAY

   The door closes by itself a set time after it has been opened. Turn the AUTO-CLOSE dial. It
   has five click positions and stops at both ends:

     Dial mark   Delay          Display
     ---------   ------------   ----------
     OFF         no delay       CLOSE 0 s
     10 s        10 seconds     CLOSE 10 s
     30 s        30 seconds     CLOSE 30 s
     1 min       1 minute       CLOSE 60 s
     3 min       3 minutes      CLOSE 180 s
     ---------   ------------   ----------
"""
