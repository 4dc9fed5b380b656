"""Keys numbered in one family: T1 / T2 / T3, M1 / M2, ZONE 1 / ZONE 2 — a guess from the key
names alone, for the manual the reader could not read them from.

A panel that prints one key per channel, memory, zone or user numbers them with one stem. When
no sentence of the manual gave them a common role, the reader reads each key on its own: a
setting of its own per key, with whatever values the lines around its label held (``t1``:
"00", "-"). The user, though, names the one setting they choose ("timer two", "the second
memory"), and no single one of those per-key settings can take it. The cheapest guess for the
closed loop is the shape such keys almost always have: **one choice setting, named by the stem,
each key going straight to its own value** (``t: t1 | t2 | t3``). The goal parser binds "timer
two" to ``t2``; the agent reads which one the display shows and repairs the rest.

Made only where every key of the family (two or more, one skill, one stem, distinct numbers)
starts nothing but a setting of its own — one no other key adjusts, on which no other setting
depends, and no on/off switch (zones or outlets switched one by one may be on together) — or
nothing at all, and where those settings hold the same values key for key (one text read for
all of them; a key with values of its own was read for itself); a family the reader gave a
shared setting (``channel`` for CH1 … CH3) is read already. Recorded as a guess
(``variables.<stem>``).
"""

from __future__ import annotations

import re
from collections import defaultdict
from typing import Any

from apbot.read.build import Builder
from apbot.read.value_keys import drop_key_roles

# a control named by a stem and a number: t1, ch2, m_3, zone_4 (never a bare digit key)
_NUMBERED = re.compile(r"([a-z]+)_?(\d{1,2})")


def read_numbered_keys(b: Builder) -> None:
    """Make each numbered key family the reader read key by key one choice setting."""
    families: dict[tuple[str, str], dict[str, str]] = defaultdict(dict)  # (skill, stem) → n → key
    for info in b.infos:
        if info.digit is not None or len(info.controls) != 1:
            continue
        m = _NUMBERED.fullmatch(info.controls[0])
        if m is None or info.skill != "press":
            continue
        families[(info.skill, m.group(1))].setdefault(m.group(2), info.name)
    for (_, stem), keys in sorted(families.items()):
        if len(keys) < 2:
            continue
        if _own_settings(b, set(keys.values())) is None:
            continue
        _replace(b, stem, keys)


def _own_settings(b: Builder, keys: set[str]) -> set[str] | None:
    """The settings the family's keys adjust, when each is one key's own (adjusted by that key
    alone, no other setting depending on it, no procedure of more than one step); None when
    any key has a role the family shares or others reach."""
    own: set[str] = set()
    for steps in b.features.values():
        touched = {a for s in steps for a in (s.get("actions") or []) if a in keys}
        if not touched:
            continue
        if len(steps) > 1 or len(touched) > 1:
            return None
        step = steps[0]
        if step.get("set") or set(step.get("actions") or []) - touched:
            return None  # sets something else too, or shares its step with other keys
        var = step.get("variable")
        if var is None:
            continue
        if any(
            var == s.get("variable")
            for other in b.features.values()
            for s in other
            if not set(s.get("actions") or []) & touched
        ):
            return None  # another key adjusts it too: a setting of the panel, not the key's
        own.add(var)
    if any(_switch(b.variables.get(var) or {}) for var in own):
        return None  # lamps switched one by one (zones, outlets): each may well be on at once
    others = {_domain(spec) for name, spec in b.variables.items() if name not in own}
    specs = [b.variables.get(var) or {} for var in own]
    if any(_scale(spec) and _domain(spec) not in others for spec in specs):
        return None  # each key steps a level of its own (a hob's zones 1-9): kept apart
    if len({_domain(b.variables.get(var) or {}) for var in own}) > 1:
        return None  # each key's own values, read for it: settings of their own after all
    for name, spec in b.variables.items():
        if name not in own and spec.get("depends_on") in own:
            return None
    return own


def _domain(spec: dict[str, Any]) -> str:
    """What a setting can hold, apart from its name: the same for every key of a family when
    the reader read one text for all of them (T1, T2, T3 each "00", "-")."""
    kept = ("type", "values", "ranges", "unit", "cases")
    return repr([spec.get(k) for k in kept])


def _scale(spec: dict[str, Any]) -> bool:
    """A numeric range of three or more steps: a level the key itself steps through (each
    zone of a hob at 1 to 9), which several keys hold at once, not a choice among the keys —
    unless another setting holds the same range (the desk's height beside M1 / M2: the keys'
    lines told nothing of their own, and the height was read for them from around)."""
    if spec.get("type") != "numeric":
        return False
    count = 0.0
    for low, high, step in spec.get("ranges") or []:
        count += (float(high) - float(low)) / float(step or 1) + 1
    return count >= 3


def _switch(spec: dict[str, Any]) -> bool:
    """An on/off setting: the reader read the key as switching something of its own."""
    return {str(v).casefold() for v in spec.get("values") or []} == {"off", "on"}


def _replace(b: Builder, stem: str, keys: dict[str, str]) -> None:
    """The keys' own settings and procedures give way to one choice setting named by ``stem``."""
    drop_key_roles(b, set(keys.values()))  # their own settings go with their procedures
    order = sorted(keys, key=int)
    values = [f"{stem}{n}" for n in order]
    name = b.unique(stem, b.variables)
    shown = {f"{stem}{n}": f"{stem}{n}".upper() for n in order}  # as the keys are printed
    spec: dict[str, Any] = {
        "type": "discrete",
        "values": values,
        "label": stem.upper(),
        "show": shown,
    }
    b.variables[name] = spec
    b.indicators.append(name)  # a lamp by each key, or the chosen one's name on the screen
    for n, value in zip(order, values, strict=True):
        key = keys[n]
        b.feature(value, [{"actions": [key], "variable": name, "effect": {"to": value}}])
    b.note(
        f"variables.{name}",
        f"keys {', '.join(keys[n] for n in order)} numbered in one family: one choice of "
        f"{name} ({', '.join(values)}), each key going to its own",
    )
