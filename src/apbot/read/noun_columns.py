"""The values a key steps through, in the column of the next table named by what it steps.

"Press VOX to step through the levels; after level 3 it is off again." and then a table
"| Display | Level | Sensitivity |": the key's values are the Level column (off, 1, 2, 3), not
the first column (what the display prints) — the sentence names the noun, the table's header
names the same noun. A sentence ending in ":" already leads its table (``evidence_lists``);
this is the sentence that does not. Apart from evidence_lists.py (near its size line) because
matching a sentence's noun to a header cell is a job of its own."""

from __future__ import annotations

import re

from apbot.read.text import Unit

_THROUGH = re.compile(
    r"\b(?:steps?|stepping|cycles?|cycling|moves?|moving|goes|go|scrolls?)\s+"
    r"(?:through|along)\s+(?:the|its)\s+(?:\w+\s+)?(?P<noun>[a-z]{3,}?)(?:e?s)\b",
    re.I,
)


def _stem(word: str) -> str:
    word = word.lower().strip(" .*()")
    return re.sub(r"(?:e?s)$", "", word) if len(word) > 4 else word


def noun_column(units: list[Unit], i: int) -> list[str] | None:
    """The cells of the column named by the noun unit ``i`` says its key steps through, in the
    table that starts within two units after it (same section)."""
    said = _THROUGH.search(units[i].text)
    if said is None or units[i].text.rstrip().endswith(":"):
        return None
    noun = _stem(said.group("noun"))
    for k in range(i + 1, min(i + 3, len(units))):
        if units[k].heading != units[i].heading:
            return None
        if not units[k].cells:
            continue
        if units[k].header:
            return None  # (a row in the middle of a table: no header of its own here)
        head = [_stem(c) for c in units[k].cells]
        if head.count(noun) != 1:
            return None
        return _column(units, k + 1, head.index(noun))
    return None


def _column(units: list[Unit], k: int, index: int) -> list[str] | None:
    """The short cells of column ``index`` in the rows from unit ``k`` on (a gloss in brackets
    dropped); none when a cell is long (a column of prose, no values)."""
    header = units[k].header if k < len(units) else ()
    items: list[str] = []
    while k < len(units) and units[k].cells and units[k].header == header:
        if index < len(units[k].cells):
            cell = re.sub(r"(?<=\w)\s*\([^)]*\)\s*$", "", units[k].cells[index].strip(" *"))
            if not cell or len(cell) > 24:
                return None
            if cell not in items:
                items.append(cell)
        k += 1
    return items if len(items) >= 2 else None


def numbered_choice(values: list[str]) -> bool:
    """Whether a choice's values are bare figures (an "off" aside: off, 1, 2, 3): such a choice
    keys a table only whose first column is headed by its own name — any chart of codes or
    counts starts its rows with the same figures."""
    figures = [v for v in values if v.lower() != "off"]
    return len(figures) >= 2 and all(re.fullmatch(r"\d{1,3}", v) for v in figures)
