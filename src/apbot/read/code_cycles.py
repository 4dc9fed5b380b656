"""A key stepping through coded values, read from the sentence that says where it wraps: "Each
press of MODE selects the next programme. After P8 the display shows P1 again."

Panels number their programmes, sounds or patterns with a letter and a figure (P1 … P8, F1 …
F5, L1 … L3). A manual often gives the run only through its wrap: the code before the wrap is
the last, the one after it the first, and every code between them is on the panel. The key the
same sentence (or paragraph) names steps through that run, whatever range another paragraph
lent its variable (a level "0 to 40" read for MODE is the intensity's, not the programmes').
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.range_codes import _actions_said
from apbot.read.shapes import _value_text

# "After P8 the display shows P1 again", "after F5 it returns to F1", "after L3 comes L1"
_CODE_WRAP = re.compile(
    r"\b(?i:after)\s+(?P<top>(?P<tp>[A-Z]{1,2})(?P<tn>\d{1,2}))\b[^.;]{0,40}?"
    r"\b(?P<bottom>(?P<bp>[A-Z]{1,2})(?P<bn>\d{1,2}))\b(?P<tail>[^.;]{0,20})"
)
_BACK = re.compile(r"\b(?:again|back|returns?|starts?\s+over|round)\b", re.I)
_MAX_CODES = 40


def code_run(text: str) -> list[str] | None:
    """The codes from the bottom to the top a wrap sentence names ("After P8 … P1 again":
    P1 … P8); None when the text names no wrap between two codes of one letter prefix."""
    for m in _CODE_WRAP.finditer(text):
        if m.group("tp") != m.group("bp") or not _BACK.search(m.group(0)):
            continue  # the same letters, and a word saying the run starts again
        low, high = int(m.group("bn")), int(m.group("tn"))
        if low >= high or high - low + 1 > _MAX_CODES:
            continue
        width = len(m.group("bn")) if m.group("bn").startswith("0") else 0
        return [f"{m.group('tp')}{str(n).zfill(width)}" for n in range(low, high + 1)]
    return None


def read_code_cycles(b: Builder) -> None:
    """Make the variable a key steps through the run of codes its wrap sentence names."""
    for at, unit in enumerate(b.manual.units):
        codes = code_run(unit.text)
        if not codes:
            continue
        keys = _actions_said(b, unit.text)
        before = b.manual.units[at - 1] if at else None
        if not keys and before is not None and before.heading == unit.heading:
            keys = _actions_said(b, before.text)  # "Each press of MODE … After P8 …"
        for var, spec in b.variables.items():
            if var == "power" or not _stepped_by(b, var, keys):
                continue
            if spec.get("type") == "discrete" and {c.lower() for c in codes} <= set(
                spec.get("values") or []
            ):
                continue
            _make_codes(spec, codes)
            b.note(f"variables.{var}.values", f"{codes[0]} … {codes[-1]}, wrapping", at)


def _stepped_by(b: Builder, var: str, keys: set[str]) -> bool:
    """Whether one of ``keys`` alone steps ``var`` to its next value."""
    for steps in b.features.values():
        for step in steps:
            acts = step.get("actions") or []
            if step.get("variable") == var and step.get("effect") == "next" and set(acts) & keys:
                return True
    return False


def _make_codes(spec: dict[str, Any], codes: list[str]) -> None:
    initial = spec.get("initial")
    for key in ("ranges", "unit", "values", "show", "entry"):
        spec.pop(key, None)
    spec["type"] = "discrete"
    spec["values"] = [_value_text(c) for c in codes]
    spec["wrap"] = True
    if initial is None or str(initial) not in spec["values"]:
        spec.pop("initial", None)
