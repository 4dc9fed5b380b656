"""A chart cell listing parts of a measure ("1/4, 1/2, 3/4 cup"): its fractions are whole
values, not numbers parted at their slashes (``cases_cells._cell_items``)."""

from __future__ import annotations

from apbot.read.cases_cells import _cell_items


def test_a_cell_of_fractions_keeps_each_fraction_whole() -> None:
    assert _cell_items("1/4, 1/2, 3/4 cup") == ["1/4", "1/2", "3/4"]
    assert _cell_items("LOW / HIGH") == ["LOW", "HIGH"]
    assert _cell_items("1/2 cup") == ["1/2"]


def test_a_lone_slash_between_levels_parts_them() -> None:
    """ "1/2" alone, "1/2 or 3": levels 1 or 2, not half of something."""
    assert _cell_items("1/2") == ["1", "2"]
    assert _cell_items("1/2 or 3") == ["1", "2", "3"]
