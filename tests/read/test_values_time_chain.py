"""A chain of clock values joined by dashes ("0:20 – 0:40 – 1:00 – 1:20") lists the values one
by one: its range runs from the first to the last, in the step between them — not from the first
to the second, as a lone pair "0:20 – 0:40" would."""

from __future__ import annotations

from apbot.read.values import Range, find_ranges


def test_a_chain_of_clock_values_is_one_stepped_range() -> None:
    assert find_ranges("Each press: 0:20 – 0:40 – 1:00 – 1:20") == [Range(1200, 4800, "s", 1200)]


def test_a_lone_pair_of_clock_values_is_still_a_range() -> None:
    assert find_ranges("from 0:20 – 1:20") == [Range(1200, 4800, "s", None)]


def test_an_unsorted_chain_gives_no_range() -> None:
    assert find_ranges("2:00 – 0:30 – 1:00") == []
