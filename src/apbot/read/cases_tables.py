"""Programme tables found among the units, and the shared cleanup of their cells.

Split out of ``cases.py`` because ``codes.py`` (display codes) reads the same tables: finding
a table's rows and matching a cell to known values is shared, applying cases is not.
"""

from __future__ import annotations

import re
from dataclasses import replace

from apbot.read.text import Unit

# A name's trailing remark in brackets, maybe cut short by the cell: "Soft steam (bio / combi)".
TRAILING_REMARK_RE = re.compile(r"\s*\([^)]*\)?$")


def _tables(units: list[Unit]) -> list[tuple[tuple[str, ...], list[Unit]]]:
    out: list[tuple[tuple[str, ...], list[Unit]]] = []
    previous: Unit | None = None
    for unit in units:
        if unit.cells and unit.header:
            last = out[-1][1][-1] if out and out[-1][0] == unit.header else None
            if last is not None and (last.line >= unit.line - 1 or last is previous):
                out[-1][1].append(unit)  # the next row, also after rows wrapped onto two lines
            else:
                out.append((unit.header, [unit]))
        previous = unit
    return out


# a sign printed after a name cell: the lamp or symbol that shows the value ("FINE   ~", "ECO ✱")
_TRAILING_MARK_RE = re.compile(r"(?<=\w)\s+[^\w\s()\[\]]{1,4}$")

_ORDINAL_RE = re.compile(r"\s*(?:no\.?\s*)?\d{1,2}[.)]?\s*", re.I)


def unnumbered(header: tuple[str, ...], rows: list[Unit]) -> tuple[tuple[str, ...], list[Unit]]:
    """A chart whose first column only numbers its rows ("| Order | Display | Mode | Drying
    time |" with rows "1 | AUTO | …"): the names are in the next column, so the numbering is
    dropped. Each returned row keeps its line; the cells lose their first one. A chart printed
    as two halves side by side ("No. | Programme | Weight | No. | Programme | Weight") is left
    alone: its columns mean one thing in the left half and another in the right."""
    if len(header) < 3 or not all(r.cells and _ORDINAL_RE.fullmatch(r.cells[0]) for r in rows):
        return header, rows
    if _norm(header[0]) in {_norm(cell) for cell in header[1:]}:
        return header, rows
    return header[1:], [replace(r, cells=r.cells[1:]) for r in rows]


def _norm(text: str) -> str:
    return re.sub(r"\s+", " ", re.sub(r"[*_`]", "", text).strip().lower()).strip(" .")


def _parent_values(cell: str, values: list[str]) -> list[str]:
    """Which of the parent's values a first cell names ("White, Quick Cook" → two)."""
    found = []
    for part in re.split(r"\s*(?:,|/|&|\band\b)\s*", _norm(cell)):
        part = re.sub(r"^\d+[.)]?\s*", "", part)
        bare = TRAILING_REMARK_RE.sub("", part)  # "PIZZA (slice)": the name, its picture aside
        bare = _TRAILING_MARK_RE.sub("", bare)  # "FINE ~", "ECO ✱": the name, its lamp's sign aside
        if part not in values and bare in values:
            part = bare
        if part in values:  # "White" is WHITE even where WHITE QUICK comes first
            found.append(part)
            continue
        for value in values:
            if part and len(part) >= 4 and value.startswith(part):
                found.append(value)
                break
    exact = _norm(cell)
    if exact in values and exact not in found:
        found = [exact]
    return found


# a note that the whole table is advice: "These are suggestions only; the console does not set
# them for you.", "The following values are recommendations.", "The guide is a recommendation"
# (not a column's: "The suggested temperatures are only suggestions" leaves the rest of the table)
_ADVICE_NOTE_RE = re.compile(
    r"^\W*(?:the\s+(?:guide|table|chart|following\s+values|values"
    r"(?:\s+(?:in|of)\s+(?:this|the)\s+(?:table|chart|guide))?)|these(?:\s+values|\s+settings)?)"
    r"\s+(?:are|is)\s+(?:only\s+)?(?:a\s+)?(?:suggestions?|recommendations?|guidance)\b",
    re.IGNORECASE,
)


# ... said with the appliance leaving them to the user: "the sharpener does not choose these
# settings itself", "the console does not set them for you" (a preset chart "recommended" but
# set by each preset, "These settings are recommendations only; adjust them", stays)
_NOT_SET_RE = re.compile(
    r"\b(?:does\s+not|doesn't|do\s+not|don't|will\s+not|won't|cannot|can't|is\s+not|are\s+not)"
    r"\s+(?:\w+\s+){0,2}?(?:set|sets|choose|select|apply|store|adjust|make)\b",
    re.IGNORECASE,
)


def advice_table(units: list[Unit], rows: list[Unit]) -> bool:
    """Whether the manual says, just before or after the table (in its section), that its values
    are only advice that the appliance does not set itself: a guide to choosing settings (knife
    → angle, pool → cycle), whose rows are then no programmes each setting depends on, however
    its first column happens to read."""
    ids = {id(u) for u in rows}
    at = [i for i, u in enumerate(units) if id(u) in ids]
    if not at:
        return False
    near = [*range(max(0, at[0] - 2), at[0]), *range(at[-1] + 1, min(at[-1] + 5, len(units)))]
    return any(  # (a footnote or two may come between: "* A very dull knife: …")
        _ADVICE_NOTE_RE.match(units[i].text)
        and units[i].heading == rows[0].heading
        and any(_left_to_user(u.text) for u in units[i : i + 2])
        for i in near
    )


# what stands before an order to the reader: a sentence's start, "please"
_ORDER_LEAD_RE = re.compile(r"(?:^|[.!?;:]|please)\W*$", re.IGNORECASE)


def _left_to_user(text: str) -> bool:
    """Whether ``text`` says the appliance does not set the values itself ("the console does
    not set them for you"): a negation with its subject, not an order to the reader ("Do not
    select JERKY for fish.", "Do not set the dryer on a soft surface.")."""
    return any(not _ORDER_LEAD_RE.search(text[: m.start()]) for m in _NOT_SET_RE.finditer(text))
