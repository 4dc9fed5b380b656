"""The actions in the manual's order, so that the reading does not depend on the list's order.

A robot's grounding lists the actions in whatever order it finds the controls, an environment's
author in whatever order they like; many of the reader's choices take the first of several
candidates (the first action of a key, the first variable named like a programme, a pad's values
in the order of its keys). Putting the actions in one order that comes from the manual before
anything is read makes every such choice the manual's: a key first mentioned earlier comes
first (the order a manual introduces its panel), its press before its turns and its hold; keys
the manual never names come after, the digits in their own order, the rest by name.
"""

from __future__ import annotations

import math

from apbot.read.actions import ActionInfo
from apbot.read.labels import Label

# one control's actions: the plain press first (the key itself), then its turns, then its hold
SKILL_ORDER = ("press", "turn_cw", "turn_ccw", "hold")


def _first_mention(token: str, labels: dict[str, Label]) -> float:
    """Where the manual first mentions the control (its first unit), or never (infinity)."""
    label = labels.get(token)
    if label is None or not label.mentions:
        return math.inf
    return float(min(label.mentions))


def manual_rank(info: ActionInfo, labels: dict[str, Label]) -> tuple[float, int, int, str]:
    """The action's place: its control's first mention (a two-key action once both are named),
    the skill, a digit's value, then the name (what is left is a tie of spelling only)."""
    at = max((_first_mention(t, labels) for t in info.controls), default=math.inf)
    skill = SKILL_ORDER.index(info.skill) if info.skill in SKILL_ORDER else len(SKILL_ORDER)
    digit = info.digit if info.digit is not None else -1
    return (at, skill, digit, info.name)


def in_manual_order(infos: list[ActionInfo], labels: dict[str, Label]) -> list[ActionInfo]:
    """The actions sorted by :func:`manual_rank`: the same list whatever order they came in."""
    return sorted(infos, key=lambda info: manual_rank(info, labels))
