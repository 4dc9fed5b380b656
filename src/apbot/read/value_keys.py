"""Keys named by the value they select: "Press 33 or 45 to select that speed. … Hold 33 and 45
together for 2 s; the display shows 78."

A panel with a key per value (speed keys 33 and 45, cup keys 1 and 2, size keys 6 and 8)
prints each key with its value, and the manual says which setting the keys choose in one
sentence naming two of them ("Press 33 or 45 to select that speed"). Read key by key, each
looks like a switch of its own. They are one setting: its values are the keys' figures (and any
figure a list of them adds, "SPEED (33 / 45 / 78)"), each key going straight to its own; a hold
of two of them that the manual says shows a further figure goes to that one.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder

_FIGURE = r"\d{1,4}"
# "Press 33 or 45 to select that speed", "Touch 1 or 2 to choose the cup size"
_CHOOSE = re.compile(
    rf"\b(?:press|touch|tap|push)\s+({_FIGURE})\s+or\s+({_FIGURE})\s+to\s+(?:select|choose|set)\s+"
    r"(?:that|the|this|a|your)\s+([a-z]+(?:\s[a-z]+)?)\b",
    re.IGNORECASE,
)
# the figures listed with slashes: "(33 / 45 / 78)", "33/45/78"
_SLASHED = re.compile(rf"(?<![\w.])({_FIGURE}(?:\s*/\s*{_FIGURE}){{2,}})(?![\w.])")


def read_value_keys(b: Builder) -> None:
    """Make the keys a sentence says select one setting by their figures that one setting."""
    figures = {  # (the key's name is its figure: a label read around it may run on)
        info.controls[0]: info
        for info in b.infos
        if info.skill == "press"
        and len(info.controls) == 1
        and re.fullmatch(_FIGURE, info.controls[0])
    }
    if len(figures) < 2:
        return
    for at, unit in enumerate(b.manual.units):
        m = _CHOOSE.search(unit.text)
        if not m or not {m.group(1), m.group(2)} <= set(figures):
            continue
        keys = {f: figures[f] for f in (m.group(1), m.group(2))}
        noun = "_".join(m.group(3).lower().split()[-1:])
        values = _all_figures(b, list(keys))
        _replace(b, noun, values, keys, _held_figure(b, list(keys), values))
        b.note(f"variables.{noun}", f"keys {', '.join(keys)} select the {noun}", at)
        return


def _all_figures(b: Builder, keys: list[str]) -> list[str]:
    """The figures a slashed list naming every key adds ("SPEED (33 / 45 / 78)"), in order."""
    for unit in [*b.manual.units]:
        for m in _SLASHED.finditer(unit.text):
            listed = [x.strip() for x in m.group(1).split("/")]
            if set(keys) <= set(listed):
                return listed
    return sorted(keys, key=int)


def _held_figure(b: Builder, keys: list[str], values: list[str]) -> tuple[str, str] | None:
    """(hold action, figure) for a hold of the keys together that the manual says shows a
    figure no key carries ("hold 33 and 45 together for 2 seconds; the display shows 78")."""
    extra = [v for v in values if v not in keys]
    hold = next(
        (i for i in b.infos if i.skill == "hold" and sorted(i.controls) == sorted(keys)),
        None,
    )
    if hold is None or not extra:
        return None
    for unit in b.manual.units:
        text = unit.text
        if re.search(r"\btogether\b", text, re.I) and all(
            re.search(rf"\b{k}\b", text) for k in keys
        ):
            for figure in extra:
                if re.search(rf"\b(?:shows?|displays?|for)\s+{figure}\b", text):
                    return hold.name, figure
    return None


def _replace(
    b: Builder,
    noun: str,
    values: list[str],
    keys: dict[str, Any],
    held: tuple[str, str] | None,
) -> None:
    """The keys' own variables and features give way to one setting ``noun``."""
    actions = {info.name for info in keys.values()} | ({held[0]} if held else set())
    old = {
        s.get("variable")
        for steps in b.features.values()
        for s in steps
        if set(s.get("actions") or []) & actions
    }
    for name in [
        n
        for n, steps in b.features.items()
        if any(set(s.get("actions") or []) & actions for s in steps)
    ]:
        del b.features[name]
    for var in old:
        if var and not any(s.get("variable") == var for st in b.features.values() for s in st):
            b.variables.pop(var, None)
            b.guards = [g for g in b.guards if var not in (g.get("when") or {})]
            b.indicators = [v for v in b.indicators if v != var]
    name = b.unique(noun, b.variables)
    b.variables[name] = {"type": "discrete", "values": values, "label": noun.upper()}
    effect = {info.name: {"to": figure} for figure, info in keys.items()}
    if held:
        effect[held[0]] = {"to": held[1]}
    b.feature(name, [{"actions": list(effect), "variable": name, "effect": effect}])
