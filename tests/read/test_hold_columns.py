"""Lengths in millimetres, and a key table's column kept for holding: each rule on a small
manual of our own words."""

from __future__ import annotations

from apbot.model.values import parse_quantity
from apbot.read import read_manual
from apbot.read.values import find_ranges, find_step

# a hedge trimmer: the blade gap set by a knob, in millimetres
TRIMMER = """
HedgePro HT-3 hedge trimmer

BLADE GAP
The blade gap is set with the GAP knob, from 10 mm to 30 mm in five steps of 5 mm.
Turn clockwise for thicker branches.
"""


def test_a_range_in_millimetres_is_read_with_its_unit_and_step() -> None:
    line = "from 10 mm to 30 mm in five steps of 5 mm"
    (found,) = find_ranges(line)
    assert (found.low, found.high, found.unit) == (10, 30, "mm")
    assert find_step(line) == (5, "mm")  # "five steps" is a count, "of 5 mm" the step


def test_a_knob_in_millimetres_becomes_a_numeric_setting_in_mm() -> None:
    model = read_manual(TRIMMER, ["turn_gap_cw", "turn_gap_ccw"]).model
    gap = model.variables["gap"]
    assert gap.type == "numeric" and gap.unit == "mm"
    assert [list(r) for r in gap.ranges] == [[10, 30, 5]]


def test_lengths_are_quantities_in_millimetres() -> None:
    assert parse_quantity("3 centimetres")[:2] == (30, "length")  # type: ignore[index]
    assert parse_quantity("45 mm")[:2] == (45, "length")  # type: ignore[index]
