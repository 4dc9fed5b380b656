"""A chart of the values a setting steps through ("It steps through this chart: | 1.0 | 1.3 |
1.6 | 2.0 | … | 128 |"): a setting whose range was read (its two ends) but no step takes the
chart's numbers as its values, when a chart of bare numbers in the manual starts at the range's
low end and ends at its high end. An uneven scale (third stops, preferred numbers, the marks
of a dial) is printed whole because no step gives it; the reader's guessed step would plan
presses the appliance does not make.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence

from apbot.read.text import Unit

_FIGURE = re.compile(r"\d+(?:[.,]\d+)?")
MIN_CHART = 6  # fewer numbers are a table's row, not a scale


def _chart_rows(units: Sequence[Unit], i: int) -> list[Unit]:
    """The rows of the table that starts at unit ``i`` (its first row and those headed by it)."""
    rows = [units[i]]
    for row in units[i + 1 :]:
        if row.header != units[i].cells:
            break
        rows.append(row)
    return rows


def charted_values(units: Sequence[Unit], low: float, high: float) -> tuple[list[str], int] | None:
    """The numbers of a chart whose every filled cell is a bare number, read row by row, rising
    throughout, with ``low`` first and ``high`` last (as printed: "1.0", "6.3", "128"); and the
    line of its first row. None when no chart fits."""
    for i, unit in enumerate(units):
        if not unit.cells or unit.header:
            continue
        cells = [c.strip() for row in _chart_rows(units, i) for c in row.cells if c.strip()]
        if len(cells) < MIN_CHART or not all(_FIGURE.fullmatch(c) for c in cells):
            continue
        numbers = [float(c.replace(",", ".")) for c in cells]
        if any(b <= a for a, b in itertools.pairwise(numbers)):
            continue
        if abs(numbers[0] - low) < 1e-9 and abs(numbers[-1] - high) < 1e-9:
            return cells, i
    return None
