"""A list of evenly spaced amounts is a range only when its unit is a unit: the word after the
last number of "pages 12, 14, 16 and 18 show the charts" is no unit (sentences our own)."""

from __future__ import annotations

from apbot.read.values import find_ranges


def test_a_word_after_a_list_of_numbers_is_no_unit() -> None:
    assert find_ranges("Pages 12, 14, 16 and 18 show the charts.") == []
    assert find_ranges("Levels 1, 2, 3 and 4 are shown by the bars.") == []


def test_a_list_in_a_real_unit_is_still_a_range() -> None:
    (found,) = find_ranges("Choose 20, 40, 60 and 80 °C.")
    assert (found.low, found.high, found.unit, found.step) == (20, 80, "°C", 20)
