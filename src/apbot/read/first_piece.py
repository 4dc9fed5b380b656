"""A range found by name that is only the first row of a range-and-step table: "Volume range /
One click of the wheel" over "50 – 100 µL 5 µL", "100 – 200 µL 10 µL", "200 – 1000 µL 25 µL".

A table heads its first column with the setting's name ("Volume range", "Time setting") and
gives one row per span with the step one click or press makes there. Found by the setting's
name anywhere in the manual, the first range of such a table is only its first row; the setting
covers every row, each with its own step.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import takewhile

from apbot.read.text import Unit
from apbot.read.values import Range
from apbot.read.values_stepped import find_stepped_pieces


def table_pieces(found: Range, units: Sequence[Unit], at: int | None) -> list[Range]:
    """Every row's range and step where ``found`` (read at unit ``at``) is the first row of a
    range-and-step table in its unit, flattened into that unit or in the rows after it under
    the same heading; [] otherwise."""
    if at is None or not 0 <= at < len(units):
        return []
    under = [u for u in units[at : at + _ROWS] if u.heading == units[at].heading]
    # the found unit and the table rows right after it, not lines of prose: those may be
    # another key's spans ("Press DELAY …: - from 1:00 to 4:00 each press adds 30 minutes; …")
    under = under[:1] + list(takewhile(lambda u: bool(u.cells), under[1:]))
    rows = ["  ".join(u.cells) if u.cells else u.text for u in under]  # as the flat line reads
    pieces = find_stepped_pieces(" ".join(rows))
    if (
        len(pieces) < 2
        or pieces[0].low != found.low
        or pieces[0].high != found.high
        or any(p.unit != found.unit for p in pieces)
    ):
        return []
    return pieces


_ROWS = 8  # a table of spans and steps runs to a few rows
