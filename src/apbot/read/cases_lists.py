"""Programme charts whose cells list a setting's choices, the default marked with a symbol
or set in square brackets.

Split out of ``cases.py``: a chart row such as "Normal   Tap Cold, Cold, Warm ▣, Hot" gives the
choices the programme offers and marks its default; the legend ("▣ = default") only names the
symbol. When the key itself was read with no values (only a guessed range), the chart's lists
are its values, in the order they first appear.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.cases_tables import _parent_values
from apbot.read.text import Unit

# "Warm ▣", "High *", "Low ◎"; a sentence's stop after the last item ("Low, High.") is no mark
_MARK_RE = re.compile(r"\s*([^\w\s(),/&'.;:!?-]+)\s*[.;:!?]?\s*$")


def _items(cell: str) -> list[tuple[str, bool]]:
    """The choices of a cell, each with whether a symbol marks it."""
    out: list[tuple[str, bool]] = []
    for raw in re.split(r"\s*,\s*", re.sub(r"\(.*?\)", "", cell)):
        bracketed = re.fullmatch(r"\s*\[([^\]]+)\]\s*[.;]?\s*", raw)  # "low, [medium], high"
        mark = None if bracketed else _MARK_RE.search(raw)
        item = bracketed.group(1) if bracketed else raw[: mark.start()] if mark else raw
        item = re.sub(r"\s+", " ", item.strip().rstrip(".;:!?").strip().lower())
        item = re.sub(r"\s+only$", "", item)
        if item and re.search(r"[a-z]", item) and len(item) <= 24:
            out.append((item, bool(mark or bracketed)))
    return out


def listed_column(rows: list[Unit], column: int) -> bool:
    """Whether two or more rows list several choices in this column ("Cold, Warm ▣, Hot")."""
    return sum(column < len(r.cells) and len(_items(r.cells[column])) >= 2 for r in rows) >= 2


def listed_cases(rows: list[Unit], column: int, pvalues: list[str]) -> dict[str, Any]:
    """A case per row: its choices, and as initial the one choice a symbol marks."""
    cases: dict[str, Any] = {}
    for row in rows:
        if column >= len(row.cells):
            continue
        items = _items(row.cells[column])
        if not items:
            continue
        case: dict[str, Any] = {"values": list(dict.fromkeys(i for i, _ in items))}
        marked = [i for i, m in items if m]
        if len(marked) == 1 and (len(items) > 1 or len(marked) == len(items)):
            case["initial"] = marked[0]
        for target in _parent_values(row.cells[0], pvalues):
            cases.setdefault(target, case)
    return cases


def as_choices(spec: dict[str, Any], cases: dict[str, Any]) -> None:
    """A key read with only a guessed range becomes a choice of the chart's listed values."""
    values = list(dict.fromkeys(v for c in cases.values() for v in c["values"]))
    for key in ("ranges", "unit", "step", "initial", "entry", "format"):
        spec.pop(key, None)
    spec["type"] = "discrete"
    spec["values"] = values
