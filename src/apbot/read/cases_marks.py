"""Charts of marks: a column per value of a setting, a row per programme, a symbol in a cell.

Split out of ``cases.py``. A chart such as "Menu | REGULAR | SOFTER | HARDER" over
"WHITE | ◎ | ● | –" says which of the setting's values each programme allows (a mark) or not
(a dash), and the legend's default mark ("◎ set when the menu is chosen (standard)") says which
one the programme starts with. Each row becomes a case of the setting; a row of dashes only
leaves the setting out of that programme.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_tables import _norm, _parent_values
from apbot.read.text import Unit
from apbot.read.text_chars import default_marks

_DASHES = {"–", "—", "-", "‐", "x", "×", "no", "n/a"}


def _mark(cell: str) -> bool | None:
    """True for a mark, False for a dash or blank, None for a cell that is neither (words)."""
    text = cell.strip().lower()
    if not text or text in _DASHES:
        return False
    if len(text) <= 2 and not re.search(r"[a-z0-9]", text):
        return True
    return None


def mark_cases(
    b: Builder, header: tuple[str, ...], rows: list[Unit], parent: str, taken: set[str]
) -> str | None:
    """Make a setting whose values head two or more mark columns depend on ``parent``, a case
    per row with a mark. Returns the setting's name, or None when the table is no such chart."""
    pvalues = b.variables[parent]["values"]
    columns = [
        c
        for c in range(1, len(header))
        if all(c < len(r.cells) and _mark(r.cells[c]) is not None for r in rows)
        and any(_mark(r.cells[c]) for r in rows)
    ]
    heads = [_norm(header[c]) for c in columns]
    for name, spec in b.variables.items():
        if name == parent or name in taken or spec.get("depends_on"):
            continue
        if spec.get("type") != "discrete" or sum(h in spec["values"] for h in heads) < 2:
            continue
        defaults = default_marks("\n".join(b.manual.lines))
        owned = _owned_heads(b, spec, heads, rows)
        cases: dict[str, Any] = {}
        charted: set[str] = set()
        for row in rows:
            marked = [
                (h, row.cells[c].strip()) for h, c in zip(heads, columns, strict=True) if h in owned
            ]
            targets = _parent_values(row.cells[0], pvalues)
            charted.update(targets)
            values = [h for h, cell in marked if _mark(cell)]
            if not values:
                continue  # no texture on this menu: the key does nothing there
            case: dict[str, Any] = {"values": values}
            first = [h for h, cell in marked if cell in defaults]
            if len(first) == 1:
                case["initial"] = first[0]
            for target in targets:
                cases.setdefault(target, case)
        if len(cases) < 2:
            continue
        # a programme the chart leaves out keeps the whole list: only a row of dashes says
        # the setting is not offered there
        for target in pvalues:
            if target not in charted:
                whole: dict[str, Any] = {"values": list(spec["values"])}
                if spec.get("initial") in spec["values"]:
                    whole["initial"] = spec["initial"]
                cases[target] = whole
        for key in ("values", "ranges", "initial"):
            spec.pop(key, None)
        spec["depends_on"] = parent
        spec["cases"] = cases
        b.note(f"variables.{name}.cases", f"depends on {parent}: a chart of marks, {len(cases)}")
        return name
    return None


def _owned_heads(b: Builder, spec: dict[str, Any], heads: list[str], rows: list[Unit]) -> set[str]:
    """The heads that are values of the setting: its own values, and a head the text outside
    the chart names with the setting ("porridge, thick … TEXTURE ×1"); a "Reheat" column
    the setting never names is no value of it."""
    label = str(spec.get("label") or "").lower()
    own = {h for h in heads if h in spec["values"]}
    chart = {id(r) for r in rows}
    texts = [u.text.lower() for u in b.manual.units if id(u) not in chart] if label else []
    for h in heads:
        said = re.compile(rf"\b{re.escape(h)}\b")
        if h not in own and any(label in t and said.search(t) for t in texts):
            own.add(h)
    return own
