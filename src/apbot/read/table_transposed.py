"""A table written sideways: its header row names the choices and each row below is one quantity
("| Mode | Sprout | Greens |" over "| Temperature | 22 °C | 20 °C |").

Apart from evidence_tables.py because which axis of a table holds one quantity is a question of
the table's cells alone. A quantity's amounts share their unit along its own axis: down a column
in a programme table written the usual way, along a row in one written sideways. So when most
data rows are each of one kind (one unit, or marks such as "yes" / "–") and most columns are
not, the header's later cells are the
choices and the first column's cells are what each choice sets.
"""

from __future__ import annotations

import re
from collections.abc import Set as AbstractSet

from apbot.read.labels import words
from apbot.read.text import Unit

# an amount and the unit after it: "22 °C" → "°c", "4 x" → "x", "0:15" → ":", "2" → ""
_AMOUNT_RE = re.compile(r"^\D{0,3}?(\d+(?:[.,:]\d+)?)\s*([^\d\s]{0,4})")


_TIME_UNITS = {"s", "sec", "secs", "min", "mins", "h", "hr", "hrs"}


def _kind_of(cell: str) -> str:
    """What a cell holds: an amount's unit ("°c", "x", ":" for a clock time, "" for a bare
    number), or ``word`` for a cell with no amount ("yes", "–", "fine")."""
    match = _AMOUNT_RE.match(cell.strip(" *"))
    if not match:
        return "word"
    unit = match.group(2).lower().rstrip(".")
    if ":" in match.group(1) or unit in _TIME_UNITS:
        return "time"  # "1:30", "45 s", "2 min": one quantity, a duration, whatever its unit
    return unit


def _one_kind(cells: list[str]) -> bool:
    """Whether the cells, two at least with an amount among them or all marks, are of one kind."""
    kinds = [_kind_of(c) for c in cells if c.strip(" *")]
    return len(kinds) >= 2 and len(set(kinds)) == 1


def sideways_choices(units: list[Unit], i: int) -> list[str] | None:
    """The header's later cells when the table headed at unit ``i`` is written sideways (most
    rows of one kind each, most columns mixed; or the header's later cells printed in capitals
    over rows of amounts, or alone); ``None`` for a table written the usual way. The columns are
    tested first: capitals in a header also head quantities ("| Programme | TEMP | TIME |"), and
    a blank first head is a grid's corner ("| | EU | US |"), not a key's name."""
    header = list(units[i].cells)
    rows = [list(u.cells) for u in units[i + 1 :] if u.header == units[i].cells and u.cells]
    rows = [r for r in rows if len(r) == len(header)]  # (a row of merged cells says nothing)
    if len(header) < 3:
        return None
    if any(re.search(r"\d", c) for c in header[1:]) or any(re.search(r"\d", r[0]) for r in rows):
        return None  # numbered rows or amounts in the header: no sideways table
    if not header[0].strip(" *"):
        return None  # "| | EU | US |": a grid's corner left blank, a spec table's columns
    by_column = sum(_one_kind([r[k] for r in rows]) for k in range(1, len(header)))
    if len(rows) >= 2 and 2 * by_column >= len(header) - 1:
        return None  # "| Programme | TEMP | TIME |": each column one quantity, written upright
    choices = [c.strip(" *") for c in header[1:] if c.strip(" *")]
    amounts = [_kind_of(c) != "word" for r in rows for c in r[1:]]
    lone = not rows and not _caps(header[0])  # "| Shade | PALE | … | DARK |" alone: its marks
    if (lone or (rows and 2 * sum(amounts) >= len(amounts))) and _printed_choices(
        choices, [r[0] for r in rows]
    ):
        # (amounts in its cells: a table of names only, "| TEMP. | SPIN |" over the lamps' names
        # of each key, lists each key's values down its column)
        return choices
    if len(rows) < 2 or all(_kind_of(c) == "word" for r in rows for c in r[1:]):
        return None  # a table of words only: no amounts to tell its axes apart
    if len({_kind_of(c) for r in rows for c in r[1:]} - {"word"}) == 1:
        # "| Programme | standard | lower end | upper end |" over rows of °C only: one unit
        # along both axes tells neither apart (a "--" or a wrapped line's word mixes a column)
        return None
    by_row = sum(_one_kind(r[1:]) for r in rows)
    if 2 * by_row <= len(rows):
        return None
    return choices


def _caps(cell: str) -> bool:
    """A cell printed in capitals (two letters at least)."""
    return cell.upper() == cell and sum(c.isalpha() for c in cell) >= 2


def _printed_choices(header: list[str], firsts: list[str]) -> bool:
    """Whether the header's later cells are names printed in capitals as the panel shows them
    ("| Mode | SOFT | CRISP | GRILL |") while the first column names quantities in plain case
    ("Temperature", "Time"): a manual prints a setting's choices as they are shown, what they
    set in prose."""
    return (
        len(header) >= 2
        and all(_caps(c) and len(c.split()) <= 3 for c in header)
        and not any(_caps(c) for c in firsts if c.strip(" *"))
    )


_COUNT_HEAD_RE = re.compile(r"\W*(?:\d{1,2}\s*(?:x|×|st|nd|rd|th)?)?\W*", re.I)
# a cell numbering a table's row, not naming anything: "1", "2.", "(3)", "①", "#4"
_ROW_NUMBER_RE = re.compile(r"\W*(?:\d{1,2}|[\u2460-\u2473\u2776-\u277f])\W*")


def _names_key(cell: str, key_words: set[str], key_names: AbstractSet[str]) -> bool:
    """Whether a row's first cell names the key: a word of four letters or more shared to its
    sixth letter, or the whole cell the key's printed name however short ("FAN", "ECO"): a
    word of three letters is too common to tie a cell to a key, a cell that is nothing else
    is the key's own name as the panel prints it."""
    first = [w for w in words(cell) if len(w) >= 4]  # "Set", "On": too short to be sure
    if any(h[:6] == w[:6] for h in first for w in key_words):
        return True
    return " ".join(words(cell)) in key_names


def key_row_marks(
    cells: tuple[str, ...],
    key_words: set[str],
    header: tuple[str, ...] = (),
    rows_below: bool = False,
    key_names: AbstractSet[str] = frozenset(),
) -> list[str] | None:
    """The cells after a row's first cell when that cell names the key (:func:`_names_key`) and
    every other cell is a name printed in capitals ("| Shade | PALE | LIGHT | DARK |" alone or
    under a row of counts, "| | 1 | 2 | 3 |"): the key's marks in order, a table written
    sideways the way "| TEMP. | SPIN |" over their columns is written upright. Cells numbering
    the row come first in a numbered table ("| 2 | SHADE | PALE | … |") and are no part of it.
    A header row with ``rows_below`` heads columns ("| Mode | LED | DISPLAY |" over its rows):
    its capitals name what each column tells, not the key's marks."""
    if len(cells) < 3 or (not header and rows_below):
        return None
    skip = 0
    while skip < len(cells) - 3 and _ROW_NUMBER_RE.fullmatch(cells[skip]):
        skip += 1  # "| 1 | LIGHT | DAWN | DAY | …": the row's number, then the key
    if header and not _over_marks(header[skip + 1 :]):
        return None  # "| Keys | Status line |": a record per key, its cells are no marks
    cells = cells[skip:]
    if not _names_key(cells[0], key_words, key_names):
        return None
    marks = [c.strip(" *") for c in cells[1:] if c.strip(" *")]
    if len(marks) < 2 or not all(_caps(m) and len(m.split()) <= 3 for m in marks):
        return None
    if any(re.search(r"[\d\[\](){}<>'.]|--", m) for m in [cells[0], *marks]):
        return None  # counts, callout letters, a drawing's frame ("CHIME [B]"): no marks row
    return marks


def _over_marks(heads: tuple[str, ...]) -> bool:
    """Whether a header's cells over a row's marks head them as one list: counts ("| | 1 | 2 |
    3 |") or blanks, or one heading followed by blanks only ("| Key | Settings | | | |"), a
    heading spanning the columns, merged in print and split cell by cell in conversion."""
    if all(_COUNT_HEAD_RE.fullmatch(h) for h in heads):
        return True
    named = [k for k, h in enumerate(heads) if h.strip(" *")]
    return len(heads) >= 3 and named == [0]
