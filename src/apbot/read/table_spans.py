"""A setting's span read across a table's column, not from the one row that named it.

Guides and charts give one row per situation, food or programme and, in a later column, the
setting each row calls for ("| Situation | Mode | Pressure |" with "1 – 2", "5 – 7", "8 – 10"
…). The row that first mentions the setting gives only a part of what it can do: the setting
reaches at least every amount its column names, so its span runs from the column's lowest to
its highest (in the row's own unit; a row in another unit says nothing of it). A table whose
rows are the models of a range ("| Model | Capacity | Temp |") gives each model its own span,
none of which this appliance reaches beyond its own row. Programme
tables read as cases (``cases.py``) still give each programme its own range afterwards.
"""

from __future__ import annotations

import re
from itertools import pairwise

from apbot.read.labels import words
from apbot.read.model_columns import is_type_number
from apbot.read.text import Unit
from apbot.read.text_sections import _MODEL_WORD_RE
from apbot.read.values import Range, find_ranges, number

_BARE_RE = re.compile(r"\s*(\d+(?:[.,]\d+)?)\s*")  # a cell that is one number: "1", "10"


def column_span(units: list[Unit], i: int, first: Range, own: set[str]) -> Range:
    """``first``, read from a later cell of table row ``i`` in the column the setting's own
    word heads (``own``: its words), widened to every amount that column gives in the table's
    other rows; ``first`` itself when it came from no such cell."""
    cells = units[i].cells
    column = next(
        (
            c
            for c in range(1, len(cells))
            if [(r.low, r.high, r.unit) for r in find_ranges(cells[c])]
            == [(first.low, first.high, first.unit)]
        ),
        None,
    )
    header = units[i].header
    if column is None or column >= len(header) or not own & set(words(header[column])):
        return first  # ("| Goal | Workout | Resist. |": another setting's column)
    rows = _table_rows(units, i)
    if (header and _MODEL_WORD_RE.search(header[0])) or all(
        is_type_number(r.cells[0]) for r in rows
    ):
        return first  # "| Model | Capacity | Temp |": each row another model's own span
        # (so too "| | Capacity | Temp |" over "| K-3 | …", "| K-5 | …": rows of type numbers)
    amounts: list[tuple[float, float]] = []
    for row in rows:
        cell = row.cells[column] if column < len(row.cells) else ""
        amounts += [(r.low, r.high) for r in find_ranges(cell) if r.unit == first.unit]
        bare = _BARE_RE.fullmatch(cell) if not first.unit else None
        if bare and (n := number(bare.group(1))) is not None:
            amounts.append((n, n))
    if _pieces(amounts, first.step):
        return first  # "| Short | 0.5 – 10 h |", "| Long | 10 – 24 h |": pieces, read as such
    low = min([first.low, *(a for a, _ in amounts)])
    high = max([first.high, *(b for _, b in amounts)])
    if (low, high) == (first.low, first.high):
        return first
    return Range(low, high, first.unit, first.step)


def _pieces(amounts: list[tuple[float, float]], step: float | None) -> bool:
    """Whether the column's amounts follow on from one another, row by row, each a span that
    starts where the one above ends (or a step on): the pieces of one range, each with its own
    step. A guide's advice overlaps and jumps, and gives single amounts ("2", "3 – 4", "9 – 12":
    in whichever order its rows come)."""
    gap = max(1.0, step or 0.0)  # (as shapes._rows_span: a gap wider than the step ends a run)
    return all(a < b for a, b in amounts) and all(
        0 <= b[0] - a[1] <= gap for a, b in pairwise(amounts)
    )


def _table_rows(units: list[Unit], i: int) -> list[Unit]:
    """The rows of the table row ``i`` stands in: the units around it under the same header."""
    header = units[i].header
    start, end = i, i
    while start > 0 and units[start - 1].cells and units[start - 1].header == header:
        start -= 1
    while end + 1 < len(units) and units[end + 1].cells and units[end + 1].header == header:
        end += 1
    return units[start : end + 1]


_RANGE_HEAD_RE = re.compile(r"^\W*(?:setting\s+|adjustment\s+|possible\s+)?ranges?\W*$", re.I)


def own_range_row(unit: Unit, own: set[str]) -> bool:
    """A row of a table that gives one setting per row ("| Section | Range | Step |" over
    "| Head (HEAD) | 0° – 60° | 5° |"): its first cell names the setting by one of its own
    words and its "Range" column holds a range. The manual's own statement of that setting's
    limits, above a range read in passing in a guide's row ("| Reflux | 15–20° | FLAT |")."""
    if not unit.cells or not unit.header or not own:
        return False
    if not own & set(words(unit.cells[0])):
        return False
    return any(
        _RANGE_HEAD_RE.match(head) and c < len(unit.cells) and find_ranges(unit.cells[c])
        for c, head in enumerate(unit.header)
        if c > 0
    )
