"""A range read from a row of a table comparing the models of a range: its own model's cell.

A specifications table with a column per model ("Feed interval | 3-10 s | 2-10 s | 1.5-12 s"
under "Model | T-100 | T-200 | T-300 PRO") gives this appliance's range only in the column of
the model the manual describes (:func:`apbot.read.model_columns.own_column`); the first cell
after the row's name is a sister model's, whose range the panel does not have.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

from apbot.read.model_columns import own_column
from apbot.read.text import Unit


def own_model_row(unit: Unit, lines: Sequence[str], units: Sequence[Unit]) -> Unit:
    """The row narrowed to its name and its own model's cell; any other unit as it is."""
    if not unit.cells or len(unit.header) != len(unit.cells) or len(unit.cells) < 3:
        return unit
    own = own_column(unit.header, lines, units)
    if own is None:
        return unit
    cells = (unit.cells[0], unit.cells[own])
    header = (unit.header[0], unit.header[own])
    return dataclasses.replace(unit, text=" | ".join(cells), cells=cells, header=header)
