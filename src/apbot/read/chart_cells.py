"""Which cells of a chart row may give a setting its range.

A chart row mixes settings: "| STEAM | 0:05 – 1:00 | 1 min | ✗ (DELAY --) |" names DELAY in
the delay column, but its range is the cooking time's. And the row's lead cell is a name:
"| Eco 40-60 | 8 kg | automatic — TEMP -- |" is no temperature range of 40 to 60. So a row
that mentions a setting gives it a range only from the column headed with that setting's
name (when the chart has one), and never from the lead cell's name.
"""

from __future__ import annotations

import dataclasses
import re

from apbot.read.labels import words
from apbot.read.shapes import _same_word
from apbot.read.text import Unit

_NAME_RE = re.compile(r"^[^\W\d_]{2,}", re.UNICODE)  # "Eco 40-60": a word leads the cell


def own_cells(unit: Unit, own_words: set[str]) -> Unit:
    """The row narrowed to the cells that may say the setting's range (its own column, or
    every cell but a leading name); a sentence, or a row whose cells do not line up with
    its header, as it is."""
    if not unit.cells or len(unit.header) != len(unit.cells) or len(unit.cells) < 2:
        return unit
    owned = [
        any(_same_word(h, w) for h in words(head) if len(h) >= 4 for w in own_words)
        for head in unit.header
    ]
    if any(owned) and not owned[0]:
        keep = owned
    elif _NAME_RE.match(unit.cells[0].strip()) and not owned[0]:
        keep = [False] + [True] * (len(unit.cells) - 1)
    else:
        return unit
    cells = tuple(c for c, k in zip(unit.cells, keep, strict=True) if k)
    header = tuple(h for h, k in zip(unit.header, keep, strict=True) if k)
    return dataclasses.replace(unit, text=" | ".join(cells), cells=cells, header=header)


def row_names(units: list[Unit]) -> list[str]:
    """The names that lead a chart's rows and hold a number ("Eco 40-60", "Quick 20'"): said in
    a sentence too, they are names, not ranges. Longest first, so a longer name goes whole."""
    names = {
        u.cells[0].strip()
        for u in units
        if u.cells
        and u.header
        and _NAME_RE.match(u.cells[0].strip())
        and re.search(r"\d", u.cells[0])
    }
    return sorted(names, key=len, reverse=True)


def without_names(text: str, names: list[str]) -> str:
    """The text with the chart's row names cut out (a range inside a name is part of it)."""
    for name in names:
        text = re.sub(rf"(?<!\w){re.escape(name)}(?!\w)", " ", text)
    return text
