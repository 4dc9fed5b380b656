"""How far along a setting's travel, said as a way of moving it: "half brightness", "the volume
halfway" is its middle; "the volume turned right down", "all the way up" an end. A scale of OFF
then levels is counted from its first working level (turned right down is quiet, not off), and
of an even count the lower middle is taken (a level of 1 … 8 halfway is 4, a brightness 10 …
100 % at half is 50 %). Only a setting named right beside the words is moved — or, for an end
with nothing named, the one the idle display shows.
"""

from __future__ import annotations

import re

from apbot.read.goal_ladders import is_off_level, ordered, ordered_values
from apbot.read.goal_text import Text, near_vocab, negated_before
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values


def _named_at(view: Model, goal: Goal, text: Text, k: int) -> VarInfo | None:
    """The one open ordered setting whose own word is the token at ``k``."""
    if not 0 <= k < len(text.tokens):
        return None
    found = [
        info
        for name, info in view.infos.items()
        if name not in goal
        and info.role == "setting"
        and ordered(info)
        and info.vocab.get(text.concepts[k], 0.0) >= 0.8
    ]
    return found[0] if len(found) == 1 else None


def halfway_levels(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set the middle of the setting "half" stands before or "halfway" stands beside."""
    for k, token in enumerate(text.tokens):
        if k in claimed:
            continue
        info = None
        start = k
        if token.text == "half":
            after = k + 2 if text.word(k + 1) in ("the", "its") else k + 1
            info = _named_at(view, goal, text, after)
        elif token.text == "halfway" or to_an_end(text, k) is not None:
            start = _phrase_start(text, k)
            if negated_before(text, start):
                continue  # "don't turn it all the way up": not that
            near = [
                i
                for name, i in view.infos.items()
                if name not in goal
                and i.role == "setting"
                and ordered(i)
                and near_vocab(i, text, start, k + 1, reach=3) >= 0.3
            ]
            info = near[0] if len(near) == 1 else None
            if not near and token.text != "halfway" and _said_of_it(text, start):
                info = _shown_idle(view, goal)  # "lower it all the way down": the desk's height
        if info is None or _named_negated(text, info, start):
            continue
        values = ordered_values(domain_values(view, info, goal))
        if len(values) > 2 and is_off_level(info, values[0]):
            values = values[1:]
        if len(values) < 3:
            continue
        end = to_an_end(text, k)
        goal[info.name] = values[(len(values) - 1) // 2 if end is None else end]
        where[info.name] = k
        claimed.add(k)


def _shown_idle(view: Model, goal: Goal) -> VarInfo | None:
    """The one open ordered setting the idle display shows: what the appliance is about, which
    "all the way up" with nothing named moves (a desk's height, a metronome's tempo)."""
    idle = str(getattr(view.model.display, "idle", "") or "")
    names = [name for name in re.findall(r"\{(\w+)\}", idle) if name in view.infos]
    if len(names) != 1 or names[0] in goal:
        return None
    info = view.infos[names[0]]
    return info if info.role == "setting" and ordered(info) else None


def to_an_end(text: Text, k: int) -> int | None:
    """0 for "right down" / "all the way down" ending at ``k``, -1 for "… up"; else None."""
    word = text.word(k)
    if word not in ("up", "down"):
        return None
    right = text.word(k - 1) == "right"
    all_the_way = [text.word(k - 3), text.word(k - 2), text.word(k - 1)] == ["all", "the", "way"]
    if not (right or all_the_way):
        return None
    return 0 if word == "down" else -1


def _phrase_start(text: Text, k: int) -> int:
    """Where the words ending at ``k`` start: "all the way up" three tokens before its "up",
    "right up" one before, "halfway" at itself — the nearness search runs from there, so a
    setting named before "all the way" is within reach."""
    if text.word(k) not in ("up", "down"):
        return k
    all_the_way = [text.word(k - 3), text.word(k - 2), text.word(k - 1)] == ["all", "the", "way"]
    return k - 3 if all_the_way else k - 1


_SAID_OF_IT = frozenset({"it", "this", "that"})
"""What stands for the appliance itself: "take it all the way up"."""


def _said_of_it(text: Text, start: int) -> bool:
    """Whether the end is said of the appliance itself — "it" right before the phrase, or no
    object at all ("all the way up, please") — rather than of some other thing ("the pedal all
    the way down", "fill the tray right up"), which the idle display says nothing about."""
    before = text.word(start - 1)
    if before in _SAID_OF_IT:
        return True
    return start == 0 or before in (",", ".", ";", ":", "and", "then", "please")


def _named_negated(text: Text, info: VarInfo, start: int) -> bool:
    """Whether the setting named just before the words is itself denied: "don't put the
    volume halfway" (the negation stands before the setting's name, out of reach of the end)."""
    for j in range(start - 1, max(-1, start - 4), -1):
        if info.vocab.get(text.concepts[j], 0.0) >= 0.3:
            return negated_before(text, j)
    return False
