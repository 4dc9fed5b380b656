"""A chart cell listing parts of a measure ("1/4, 1/2, 3/4 cup"): its fractions are whole
values, not numbers parted at their slashes (``cases_cells._cell_items``)."""

from __future__ import annotations

from apbot.read.cases_cells import _cell_items


def test_a_cell_of_fractions_keeps_each_fraction_whole() -> None:
    assert _cell_items("1/4, 1/2, 3/4 cup") == ["1/4", "1/2", "3/4"]
    assert _cell_items("LOW / HIGH") == ["LOW", "HIGH"]
