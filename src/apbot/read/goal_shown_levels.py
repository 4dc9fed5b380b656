"""Values named the way the panel shows or numbers them, read before quantities go to settings.

- A value shown as a short label and a number ("pH 9.5", "pH 10.0" for the levels of a water
  selector) is named by that label and the number said ("pH nine and a half", "pH ten"): the
  user reads the display, not the value's inner name.
- Values that are numbered levels of a word (ALKALINE 1-4, ACIDIC 1-2 of one selector) are
  named by the word with a level ("alkaline level one") or an end of its levels ("the strongest
  alkaline", "the mildest acidic", "the weaker acidic" of two): a higher level is more of it.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model, VarInfo
from apbot.read.goal_vocab import HIGHEST, LOWEST, stem
from apbot.read.numbers import find_mentions

_SHOWN = re.compile(r"^\s*([A-Za-z]{1,6})\s*(\d+(?:\.\d+)?)\s*$")
_NUMBERED = re.compile(r"^([a-z]+)[ _-]?(\d+)$")
_MORE = frozenset({"stronger", "higher", "more"})
_LESS = frozenset({"weaker", "milder", "lower", "less", "gentler", "softer"})


def shown_levels(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set a selector whose value the words name by its display text or its numbered level."""
    for name, info in view.infos.items():
        if name in goal or info.role != "setting" or not isinstance(info.var, DiscreteVariable):
            continue
        found = _by_display(info, text, claimed) or _by_level(info, text, claimed)
        if found is not None:
            value, start, end = found
            goal[name] = value
            where[name] = start
            claimed.update(range(start, end))


def _by_display(info: VarInfo, text: Text, claimed: set[int]) -> tuple[Any, int, int] | None:
    """ "pH nine": a label shared by two or more shown values, then the number of one."""
    show = info.var.show if isinstance(info.var.show, dict) else {}
    shown: dict[str, dict[float, Any]] = {}
    for value in info.values:
        match = _SHOWN.match(str(show.get(str(value), "")))
        if match:
            shown.setdefault(match[1].casefold(), {})[float(match[2])] = value
    labels = {label: by for label, by in shown.items() if len(by) >= 2}
    if not labels:
        return None
    for mention in find_mentions(text.tokens, skip=claimed):
        by = labels.get(text.word(mention.start - 1).casefold())
        if mention.kind == "number" and by is not None and mention.value in by:
            return by[mention.value], mention.start - 1, mention.end
    return None


def _by_level(info: VarInfo, text: Text, claimed: set[int]) -> tuple[Any, int, int] | None:
    """ "alkaline level one", "the strongest acidic": a word two or more values number."""
    families: dict[str, dict[int, Any]] = {}
    for value in info.values:
        match = _NUMBERED.match(str(value).casefold())
        if match:
            families.setdefault(stem(match[1]), {})[int(match[2])] = value
    families = {word: levels for word, levels in families.items() if len(levels) >= 2}
    for k, word in enumerate(text.stems):
        levels = families.get(word)
        if levels is None or k in claimed:
            continue
        end = _end_said(text, k, len(levels))
        if end is not None:
            return levels[(max if end else min)(levels)], k, k + 1
        number = _level_number(text, k, claimed)
        if number is not None and number[0] in levels:
            return levels[number[0]], k, number[1]
    return None


def _end_said(text: Text, k: int, count: int) -> bool | None:
    """True for the top of the levels named at ``k`` ("the strongest alkaline", "highest
    alkaline level"), False for the bottom, None when no end is said just before it."""
    j = k - 1
    while j > 0 and text.word(j) in ("the", "a", "its"):
        j -= 1
    word = text.word(j)
    if word in HIGHEST or (count == 2 and word in _MORE):
        return True
    if word in LOWEST or (count == 2 and word in _LESS):
        return False
    return None


def _level_number(text: Text, k: int, claimed: set[int]) -> tuple[int, int] | None:
    """ "alkaline level one", "alkaline 3": the level number right after the word (and the end
    of what was said)."""
    j = k + 1 if text.word(k + 1) == "level" else k
    for mention in find_mentions(text.tokens, skip=claimed):
        if mention.start == j + 1 and mention.kind == "number" and mention.value.is_integer():
            return int(mention.value), mention.end
    return None
