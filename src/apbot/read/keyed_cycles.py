"""Cycles printed one per key, each after the key's name: "NATURE: N1 → N2 → N3 → N1 …
NOISE: S1 → S2 → S1 …".

A panel with a key per group (a family of sounds, a bank of programmes, a channel's patterns)
lists what each key steps through on a line of its own that starts with the key's name. Lines
like these run together into one paragraph when the manual is flattened, so no list is read
from the paragraph as a whole; cut at each key's name, every piece is one key's cycle. The
variable the key steps takes that cycle, whatever a looser reading gave it before.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.shapes import _value_text
from apbot.read.value_lists import find_list


def read_keyed_cycles(b: Builder) -> None:
    """Give each key its own cycle where a paragraph prints one cycle after each key's name."""
    steppers = _steppers(b)
    if not steppers:
        return
    for at, unit in enumerate(b.manual.units):
        if "→" not in unit.text and "->" not in unit.text:
            continue
        marks = sorted(
            (m.start(), m.end(), label)
            for label in steppers
            for m in re.finditer(rf"(?<![\w-]){re.escape(label)}\s*:", unit.text)
        )
        if len(marks) < 2:
            continue  # one key's name before a list says less: two at least make the pattern
        ends = [start for start, _end, _label in marks[1:]] + [len(unit.text)]
        for (_start, end, label), stop in zip(marks, ends, strict=True):
            found = find_list(unit.text[end:stop])
            if not found or found[1] != "arrows" or len(found[0]) < 2:
                continue
            var, step = steppers[label]
            step["effect"] = "next"  # (an on/off read for want of values steps the cycle)
            values = list(dict.fromkeys(_value_text(v) for v in found[0]))
            _make_cycle(b.variables[var], values)
            b.note(f"variables.{var}.values", f"{label}: {' → '.join(values)}", at)


def _steppers(b: Builder) -> dict[str, tuple[str, dict[str, Any]]]:
    """Printed key name → the variable its press alone steps (to the next value, or on and
    off for want of values) and that step."""
    out: dict[str, tuple[str, dict[str, Any]]] = {}
    for steps in b.features.values():
        for step in steps:
            acts = step.get("actions") or []
            var = step.get("variable")
            if len(acts) != 1 or step.get("effect") not in ("next", "toggle") or not var:
                continue
            if var == "power" or (step["effect"] == "toggle" and _values(b, var) != ["off", "on"]):
                continue
            info = next((i for i in b.infos if i.name == acts[0]), None)
            if info is None or info.skill != "press" or len(info.controls) != 1:
                continue
            label = b.labels.get(info.controls[0])
            if label is not None and label.text and len(label.text) >= 2:
                out[label.text] = (var, step)
    return out


def _values(b: Builder, var: str) -> list[str]:
    return [str(v) for v in b.variables.get(var, {}).get("values") or []]


def _make_cycle(spec: dict[str, Any], values: list[str]) -> None:
    initial = spec.get("initial")
    for key in ("ranges", "unit", "format", "values", "show", "entry"):
        spec.pop(key, None)
    spec["type"] = "discrete"
    spec["values"] = values
    spec["wrap"] = True
    if initial is None or str(initial) not in values:
        spec.pop("initial", None)
