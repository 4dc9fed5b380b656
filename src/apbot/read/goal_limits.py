"""Alarm limits said as what they guard against: "warn me if it drops below 18 degrees or goes
above 26" sets the LOW limit to 18 and the HIGH limit to 26. A model with a pair of limits (one
named low/min, one high/max) takes a number said after "below"/"under" as its low limit and one
after "above"/"over" as its high limit, whatever unit each was said in — read before quantities
go to the setting of their kind, which would give both to the one that has a unit."""

from __future__ import annotations

from typing import Any

from apbot.read.goal_fit import fit
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_unitless import listed_number
from apbot.read.goal_values import name_words
from apbot.read.goal_view import Goal, Model, VarInfo, own_stems
from apbot.read.numbers import Mention

_BELOW = frozenset({"below", "under", "beneath"})
_ABOVE = frozenset({"above", "over", "exceeds", "exceed", "beyond"})
_LOW_NAMES = frozenset({"lo", "low", "min", "minimum", "lower"})
_HIGH_NAMES = frozenset({"hi", "high", "max", "maximum", "upper"})


def limit_numbers(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
) -> list[Mention]:
    """Give each number said after "below" / "above" to the low / high limit; the rest left."""
    low = _named(view, _LOW_NAMES)
    high = _named(view, _HIGH_NAMES)
    if not low or not high:
        return mentions
    left: list[Mention] = []
    for mention in mentions:
        before = text.word(mention.start - 1)
        side = low if before in _BELOW else high if before in _ABOVE else []
        fits = [
            (info, v)
            for info in side
            if info.name not in goal and not _said_of_another(view, text, mention.start - 1, info)
            if (v := _value(view, info, mention, goal)) is not None
        ]
        if len(fits) != 1:
            left.append(mention)
            continue
        info, value = fits[0]
        goal[info.name] = value
        where[info.name] = mention.start
        claimed.update(range(mention.start - 1, mention.end))
    return left


_PART_ENDS = CLAUSE_ENDS | {",", "and", "or", "but"}


def _said_of_another(view: Model, text: Text, k: int, info: VarInfo) -> bool:
    """A setting other than the limit is named in the words before "below" / "above" at ``k``
    (its part of the sentence): "the upper zone just under 11 °C" gives 11 to the UPPER zone,
    a place, not to a LOWER one as its lower limit; "the tank falls below 21" names none."""
    own = own_stems(info)
    j = k - 1
    while j >= 0 and text.word(j) not in _PART_ENDS:
        said = text.stems[j]
        if said not in own and any(
            said in own_stems(other) for other in view.infos.values() if other is not info
        ):
            return True
        j -= 1
    return False


def _named(view: Model, words: frozenset[str]) -> list[VarInfo]:
    """The settings whose name or label holds one of ``words`` (LO ALARM, "Max temp"): the
    limits of one side; a model with none on either side has no pair and the rule stays out."""
    return [
        info
        for info in view.infos.values()
        if info.role == "setting"
        and words & {w.casefold() for w in name_words(f"{info.name} {info.var.label or ''}")}
    ]


def _value(view: Model, info: VarInfo, mention: Mention, goal: Goal) -> Any:
    """The limit's value for the number: as its kind fits it, or its bare number as said."""
    value = fit(view, info, mention, goal)
    if value is not None:
        return value
    if mention.kind not in ("number", "quantity"):
        return None
    said = mention.value if mention.kind == "number" else _said_number(mention)
    return None if said is None else listed_number(view, info, goal, said)


def _said_number(mention: Mention) -> float | None:
    """A temperature's number as said (its base unit is the degree Celsius), else none."""
    return mention.value if mention.dimension == "temperature" else None
