"""A key's choices from a press-count table in its own section ("| Press | Icon | Pattern |" over
"| — | ◔ | steady |", "| 1st | ◑ | pulse |", …, "| 3rd | ◔ | back to steady |").

Apart from count_tables.py, which reads a chart of amounts counted in presses as a range: here the
rows name what each press selects in words, so the column of words, row by row, is the key's list
of choices in the order the presses reach them; a row "back to …" closes the cycle. Asked only
for a key the reader would otherwise guess an on/off of its own, so a list read the usual way is
never displaced.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from apbot.read.text import Unit

# the head of the column counting presses ("Press", "Presses", "No. of presses", "Touches")
_COUNT_HEAD_RE = re.compile(
    r"(?:no\.?\s+of\s+|number\s+of\s+)?(?:press(?:es)?|touch(?:es)?|taps?)", re.IGNORECASE
)
# a row's count: a figure, an ordinal, a dash or a word for the start ("—", "0", "1st", "start")
_COUNT_CELL_RE = re.compile(r"[—–\-]|\d{1,2}(?:st|nd|rd|th|x|×)?|none|start|first", re.IGNORECASE)
_BACK_RE = re.compile(r"^(?:back|returns?|again)\b", re.IGNORECASE)


def pressed_names(units: Sequence[Unit], name: str, label: str) -> tuple[list[str], int] | None:
    """The choices a key steps through, from a table in the section whose heading names the key
    (a heading word starting with a word of its name or label, three letters at least) whose
    first column counts presses: the first later column whose every cell is words (no figure),
    read down to a row going back to the start; with the unit of its first row. None when no
    such table stands there or it names fewer than two choices."""
    own = {w for w in re.findall(r"[a-z]+", f"{name} {label}".lower()) if len(w) >= 3}
    if not own:
        return None
    for i, unit in enumerate(units):
        if not (unit.cells and unit.header and _COUNT_HEAD_RE.fullmatch(unit.header[0].strip())):
            continue
        heading = re.findall(r"[a-z]+", unit.heading.lower())
        if not any(h.startswith(w) for h in heading for w in own):
            continue
        rows = [u.cells for u in units[i:] if u.cells and u.header == unit.header]
        if len(rows) < 2 or not all(_COUNT_CELL_RE.fullmatch(r[0].strip()) for r in rows):
            return None
        column = _words_column(rows, len(unit.header))
        return (_without_own_noun(column, own), i) if column else None
    return None


def _words_column(rows: list[tuple[str, ...]], width: int) -> list[str] | None:
    """The first column after the count whose cells are all words (two letters at least, no
    figure), down to a row going back to the start; its distinct cells, two or more."""
    for k in range(1, width):
        names: list[str] = []
        for row in rows:
            cell = row[k].strip(" *") if k < len(row) else ""
            if _BACK_RE.match(cell):
                break
            if not re.search(r"[A-Za-z]{2}", cell) or re.search(r"\d", cell):
                names = []
                break
            names.append(cell.lower())
        if len(names) >= 2 and len(set(names)) == len(names):
            return names
    return None


def _without_own_noun(names: list[str], own: set[str]) -> list[str]:
    """The names less a last word that is the key's own noun ("quarter notes", "eighth notes"
    for NOTE: quarter, eighth), which the user's sentence leaves out as the key already says it;
    kept when dropping it would leave a name empty or two names alike."""
    short = [
        n.rsplit(" ", 1)[0] if " " in n and n.rsplit(" ", 1)[1].rstrip("s") in own else n
        for n in names
    ]
    return short if len(set(short)) == len(short) else names
