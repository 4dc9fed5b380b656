"""Two values of one setting said together name its value for both: "flash and sound
together" is SOUND+FLASH, "the rain head and the handset" BOTH. A panel that lets a user pick
one of two outlets or signals, or both, names the third value by the other two (BOTH, ALL, or
the two joined: "SOUND+FLASH"); a user names the two."""

from __future__ import annotations

import re
from collections.abc import Sequence
from itertools import pairwise
from typing import Any

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import CONNECTORS, Text
from apbot.read.goal_view import Goal, Model, VarInfo

_BOTH_WORDS = frozenset({"both", "all", "together"})
# what may stand between the two values: "flash and sound", "the rain head and the handset"
_BETWEEN = CONNECTORS | {"the", "its", "a"}


def _both_of(info: VarInfo) -> tuple[Any, set[Any]] | None:
    """The value for both and the two it joins, or None: BOTH (ALL) among three values, or a
    value named or shown as two others joined ("SOUND+FLASH")."""
    if not isinstance(info.var, DiscreteVariable):
        return None
    values = list(info.values)
    show = info.var.show if isinstance(info.var.show, dict) else {}
    names = {v: {str(v).casefold(), str(show.get(str(v), "")).casefold()} - {""} for v in values}
    for value in values:
        others = [v for v in values if v != value]
        if len(values) == 3 and str(value).casefold() in _BOTH_WORDS:
            return value, set(others)
        for name in names[value]:
            parts = [p.strip() for p in re.split(r"\s*(?:\+|&|/|\band\b)\s*", name) if p.strip()]
            if len(parts) != 2:
                continue
            joined = {v for v in others for part in parts if part in names[v]}
            if len(joined) == 2:
                return value, joined
    return None


def both_values(
    view: Model,
    text: Text,
    matches: Sequence[Any],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
) -> None:
    """Where the two values a BOTH joins are matched side by side (only connectors and
    articles between them), the setting takes the BOTH value."""
    for name, info in view.infos.items():
        both = _both_of(info)
        if both is None or info.role != "setting":
            continue
        value, pair = both
        found = sorted(
            (m.start, m.end, m.value) for m in matches if m.var == name and m.value in pair
        )
        for (s1, e1, v1), (s2, e2, v2) in pairwise(found):
            between = range(e1, s2)
            if v1 == v2 or s2 < e1 or len(between) > 4:
                continue
            # the first value's noun may follow it: "the rain head and the handset"
            rest = between[1:] if between and text.word(e1).isalpha() else between
            span = range(s1, e2)
            if any(k in claimed for k in span) and where.get(name) not in span:
                continue  # "in white and blue" read whole as another setting's value
            if all(text.word(k) in _BETWEEN for k in rest) and any(
                text.word(k) in ("and", "&", "+", "with") for k in between
            ):
                goal[name] = value
                where[name] = s1
                claimed.update(range(s1, e2))
                break
