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
from apbot.read.labels import words
from apbot.read.range_codes import _actions_said
from apbot.read.shapes import _value_text

# "After P8 the display shows P1 again", "after F5 it returns to F1", "after L3 comes L1"
# (set16: a display label and a figure, "After CH 22 comes CH 01": the figure is the value)
_CODE_WRAP = re.compile(
    r"\b(?i:after)\s+(?P<top>(?P<tp>[A-Z]{1,2})(?P<ts> ?)(?P<tn>\d{1,2}))\b[^.;]{0,40}?"
    r"\b(?P<bottom>(?P<bp>[A-Z]{1,2})(?P<bs> ?)(?P<bn>\d{1,2}))\b(?P<tail>[^.;]{0,20})"
)
_BACK = re.compile(r"\b(?:again|back|returns?|starts?\s+over|round|comes)\b", re.I)
_MAX_CODES = 40


def code_run(text: str) -> list[str] | None:
    """The codes from the bottom to the top a wrap sentence names ("After P8 … P1 again":
    P1 … P8); None when the text names no wrap between two codes of one letter prefix."""
    for m in _CODE_WRAP.finditer(text):
        if m.group("tp") != m.group("bp") or not _BACK.search(m.group(0)):
            continue  # the same letters, and a word saying the run starts again
        if m.group("ts") != m.group("bs"):
            continue  # ("CH 22" and "C1": two ways of writing, no one run)
        low, high = int(m.group("bn")), int(m.group("tn"))
        if low >= high or high - low + 1 > _MAX_CODES:
            continue
        width = len(m.group("bn")) if m.group("bn").startswith("0") else 0
        sep = m.group("ts")
        return [f"{m.group('tp')}{sep}{str(n).zfill(width)}" for n in range(low, high + 1)]
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
        said = set(words(unit.text)) | (set(words(before.text)) if before is not None else set())
        for var, spec in b.variables.items():
            if var == "power" or not _stepped_by(b, var, keys, said):
                continue
            if spec.get("type") == "discrete" and {c.lower() for c in codes} <= set(
                spec.get("values") or []
            ):
                continue
            _make_codes(spec, codes)
            b.note(f"variables.{var}.values", f"{codes[0]} … {codes[-1]}, wrapping", at)


def _stepped_by(b: Builder, var: str, keys: set[str], said: set[str]) -> bool:
    """Whether one of ``keys`` alone steps ``var`` to its next value, or a pair of them steps
    it both ways and the sentences name it ("Press ▲ or ▼ while the display shows the
    channel … After CH 22 comes CH 01": the channel's run, not the other settings' the pair
    changes in their own views)."""
    for steps in b.features.values():
        for step in steps:
            acts = step.get("actions") or []
            if step.get("variable") != var or not set(acts) & keys:
                continue
            effect = step.get("effect")
            if effect == "next":
                return True
            if isinstance(effect, dict) and set(words(var.replace("_", " "))) <= said:
                return True
    return False


def _make_codes(spec: dict[str, Any], codes: list[str]) -> None:
    initial = spec.get("initial")
    for key in ("ranges", "unit", "values", "show", "entry"):
        spec.pop(key, None)
    spec["type"] = "discrete"
    spec["values"] = [_value_text(c) for c in codes]
    label = codes[0].rpartition(" ")[0]
    if label:  # "CH 01" … "CH 22": the display's label before the figure, the figure the value
        spec["values"] = [c.rpartition(" ")[2] for c in codes]
        spec["show"] = f"{label} {{value}}"
    spec["wrap"] = True
    if initial is None or str(initial) not in spec["values"]:
        spec.pop("initial", None)
