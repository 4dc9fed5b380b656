"""Amounts typed on the number keys after a choice key ("Press AUTO DEFROST to choose the food.
Enter the weight with the number keys."): the second step of that key's feature."""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.values import find_ranges

# the step after choosing: what is typed next ("Enter the weight of the food in grams")
_ENTER_RE = re.compile(
    r"^(?:\d+[.)]\s*)?(?:then\s+)?(?:enter|type|key in|input)\s+(?:the\s+|a\s+)?"
    r"(weight|quantity|amount|number of (?:portions|servings|pieces|cups)|portions|servings)\b"
    r"([^.]*)",
    re.I,
)
_UNITS = {"gram": "g", "grams": "g", "g": "g", "kg": "g", "kilograms": "g", "ounces": "oz"}


def assign_keyed_amounts(b: Builder, digits: list[str]) -> None:
    """For each key that steps a list of choices, an amount the next step of its procedure types
    on the number keys becomes a second step of the key's feature (its range from the units that
    follow, in the amount's unit; guessed wide where none is printed)."""
    if not digits:
        return
    units = b.manual.units
    for fname, steps in list(b.features.items()):
        if len(steps) != 1 or steps[0].get("effect") != "next":
            continue
        var = steps[0].get("variable")
        if not var or b.variables.get(var, {}).get("type") != "discrete":
            continue
        key = steps[0]["actions"][0]
        info = next((i for i in b.infos if i.name == key), None)
        if info is None or len(info.controls) != 1 or info.controls[0] not in b.labels:
            continue
        found = _typed_after(b, b.labels[info.controls[0]].mentions)
        if found is None:
            continue
        noun, unit, start, at = found
        ranges = [
            r
            for u in units[start : at + 10]
            if u.heading == units[at].heading
            for r in find_ranges(u.text)
            if r.unit == unit
        ]
        low = min((r.low for r in ranges), default=1 if unit == "" else 100)
        high = max((r.high for r in ranges), default=9 if unit == "" else 3000)
        name = b.unique(noun.replace(" ", "_"), b.variables)
        spec: dict[str, Any] = {
            "label": noun.upper(),
            "type": "numeric",
            "ranges": [[low, high, 1]],
            "unit": unit,
            "entry": {"format": "number"},
        }
        b.variables[name] = spec
        steps.append({"actions": list(digits), "variable": name})
        what = f"range {low:g}–{high:g} {unit}" if ranges else "range guessed (none printed)"
        b.note(f"features.{fname}", f"then the number keys enter the {noun} ({what})", at)


def _typed_after(b: Builder, mentions: list[int]) -> tuple[str, str, int, int] | None:
    """The amount a step right after one of the key's mentions types: its noun, its unit, the
    mention's and the step's unit index."""
    units = b.manual.units
    for i in mentions:
        prose = 0
        for k in range(i + 1, min(i + 16, len(units))):
            if units[k].heading != units[i].heading:
                break
            if units[k].cells:
                continue  # the table of choices between the two steps
            prose += 1
            if prose > 2:
                break
            m = _ENTER_RE.search(units[k].text)
            if not m:
                continue
            noun = m.group(1).lower()
            said = re.search(r"\bin\s+(grams|g|kilograms|kg|ounces)\b", m.group(2), re.I)
            unit = _UNITS[said.group(1).lower()] if said else ("g" if noun == "weight" else "")
            if noun.startswith("number of"):
                noun = noun.split()[-1]
            return noun, unit, i, k
    return None
