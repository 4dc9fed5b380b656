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
# "Press T1, T2 or T3 to choose that channel": a key per value, named
_KEY = r"[A-Za-z0-9][\w+-]{0,9}"
_CHOOSE_NAMED = re.compile(
    rf"\b(?:press|touch|tap|push)\s+({_KEY}(?:\s*,\s*{_KEY})*,?\s+or\s+{_KEY})\s+to\s+"
    r"(?:select|choose|set)\s+(?:that|the|this|a|your)\s+([a-z]+)\b",
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
    if len(figures) >= 2:
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
    _named_keys(b)


def _named_keys(b: Builder) -> None:
    """Keys printed with names, each choosing one of a setting's values: "Press T1, T2 or T3
    to choose that channel" (every listed word a key of the panel): one setting whose values
    are the keys' names, each key going straight to its own."""
    named = {
        b.labels[info.controls[0]].text.upper(): info
        for info in b.infos
        if info.skill == "press"
        and len(info.controls) == 1
        and info.digit is None
        and info.controls[0] in b.labels
        and b.labels[info.controls[0]].line is not None
    }
    if len(named) < 2:
        return
    for at, unit in enumerate(b.manual.units):
        m = _CHOOSE_NAMED.search(unit.text)
        if not m:
            continue
        listed = [k.upper() for k in re.split(r"\s*,\s*|\s+or\s+", m.group(1)) if k]
        if len(listed) < 2 or len(set(listed)) != len(listed) or not set(listed) <= set(named):
            continue
        if any(re.fullmatch(_FIGURE, k) for k in listed):
            continue  # (figure keys: the rule above)
        keys = {k.lower(): named[k] for k in listed}
        own = {info.name for info in keys.values()}
        if any(
            {a for st in steps for a in st.get("actions") or []} - own
            for steps in b.features.values()
            if any(set(st.get("actions") or []) & own for st in steps)
        ):
            continue  # "Z1 then ▲ / ▼": the keys choose which setting other keys move
        if _step_numbers(b, own):
            continue  # "Press UP or DOWN to set the temperature": the keys step a number
        noun = m.group(2).lower()
        name = _replace(b, noun, list(keys), keys, None)
        if _lamps_named(b, listed):  # "the lamp of the chosen channel is lit (T1, T2 or T3)"
            b.variables[name]["show"] = {k.lower(): k for k in listed}
        b.note(f"variables.{noun}", f"keys {', '.join(listed)} each choose a {noun}", at)
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


def drop_key_roles(b: Builder, actions: set[str]) -> None:
    """Forget what the reader made of ``actions`` key by key — the procedures they take part in,
    and the settings only those procedures adjusted (with their guards and lamps) — before the
    keys are read again as one setting."""
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


def _replace(
    b: Builder,
    noun: str,
    values: list[str],
    keys: dict[str, Any],
    held: tuple[str, str] | None,
) -> str:
    """The keys' own variables and features give way to one setting ``noun`` (its name)."""
    drop_key_roles(b, {info.name for info in keys.values()} | ({held[0]} if held else set()))
    name = b.unique(noun, b.variables)
    b.variables[name] = {"type": "discrete", "values": values, "label": noun.upper()}
    effect = {info.name: {"to": figure} for figure, info in keys.items()}
    if held:
        effect[held[0]] = {"to": held[1]}
    b.feature(name, [{"actions": list(effect), "variable": name, "effect": effect}])
    return name


def _step_numbers(b: Builder, own: set[str]) -> bool:
    """Whether any of the keys already steps a number or a time ("Press UP or DOWN to set the
    temperature", "Press HOUR or MIN to set the clock"): keys that move a setting through its
    range, not keys each going to a value named after them."""
    return any(
        (b.variables.get(st.get("variable") or "") or {}).get("type") in ("numeric", "time")
        for steps in b.features.values()
        for st in steps
        if set(st.get("actions") or []) & own
    )


def _lamps_named(b: Builder, keys: list[str]) -> bool:
    """Whether a sentence about lamps or the screen names every key: the choice lights the
    key's own name ("Channel lamps: the lamp of the chosen channel is lit (T1, T2 or T3)")."""
    return any(
        re.search(r"\b(?:lamps?|lights?|lit|shows?|screen|display)\b", u.text, re.I)
        and all(re.search(rf"(?<![\w-]){re.escape(k)}(?![\w-])", u.text) for k in keys)
        for u in b.manual.units
    )
