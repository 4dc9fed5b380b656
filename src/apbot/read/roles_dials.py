"""A dial lent to other keys as their stepping pair: the one dial turned both ways as the shared
adjuster, and a dial turned right after setting keys are pressed.

Apart from ``roles`` because it is a question about the panel's dials, not about the order the
roles are given in.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_common import label_of, turns


def _lend_dial(
    pairs: dict[str, dict[str, list[str]]], dials: dict[str, list[ActionInfo]]
) -> str | None:
    """With no unnamed stepping pair, the one dial turned both ways is the adjuster a key may
    switch between settings, as a + / − pair is (its turns up and down): the token lent."""
    if "" in pairs or len(dials) != 1:
        return None
    token, moves = next(iter(dials.items()))
    cw, ccw = turns(moves)
    if not cw or not ccw:
        return None
    pairs[""] = {"up": list(cw), "down": list(ccw)}
    return token


def _turned_after_keys(b: Builder, dial: str, keys: list[ActionInfo]) -> bool:
    """A dial that picks a list of its own is also turned after setting keys ("Press TEMP and
    turn the dial to set the temperature"): those keys take its turns as their stepping pair."""
    noun = re.escape(dial.split("_")[0])
    labels = [re.escape(label_of(b, k.controls[0])) for k in keys if k.controls[0] in b.labels]
    if not labels:
        return False
    said = re.compile(
        rf"\b(?:press|touch|push)\w*\s+(?:the\s+)?(?:{'|'.join(labels)})\b[^.]{{0,30}}?"
        rf"\bturn\w*\s+the\s+(?:\w+\s+)?{noun}\b",
        re.IGNORECASE,
    )
    return any(said.search(u.text) for u in b.manual.units)
