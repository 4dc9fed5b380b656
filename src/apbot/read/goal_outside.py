"""A number said beside a setting's own name, outside the values read for it: kept, and said so.

Only for a read belief (``parse_instruction(..., outside=[...])``). A range read from a manual
is often the wrong one — the spec table's first row, another mode's range, two example values
taken for the ends — so "temper at 33" on a TEMPER setting read as 40 … 55 °C may well be what
the appliance offers. Dropping the number silently loses what the user asked; guessing another
setting for it is worse. So a bare number whose nearest words are one numeric setting's own
name (its name or its key's label, with no comma or clause end between) is given to that setting
as said, and the reason it lies outside the belief is noted in ``outside``: the closed loop then
looks for it on the display, and the note names the words and why.
"""

from __future__ import annotations

from typing import Any

from apbot.model.schema import DiscreteVariable, NumericVariable
from apbot.model.values import preview
from apbot.read.goal_error import GoalParseError
from apbot.read.goal_fit import fit
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_values import bare_number
from apbot.read.goal_view import Goal, Model, VarInfo, domain_values, own_concepts
from apbot.read.numbers import Mention

REACH = 3
"""Tokens between the number and the setting's own word, at most (either side)."""


def kept_outside(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
    outside: list[str],
) -> None:
    """Give each unclaimed bare number the numeric setting whose own word stands right beside
    it, as said, when that setting's read values lack it; note why in ``outside``."""
    for mention in mentions:
        if mention.kind != "number" or mention.unit:
            continue
        if any(k in claimed for k in range(mention.start, mention.end)):
            continue
        if _not_a_value(text, mention):
            continue  # "not fridge 9", "above 9", "opened 20 times": no value asked for
        info = _nearest_setting(view, text, mention, goal)
        if info is None or fit(view, info, mention, goal) is not None:
            continue  # (a value it has was left for a reason of its own)
        values = domain_values(view, info, goal)
        numbers = [n for n in (bare_number(v) for v in values) if n is not None]
        if numbers and all((n < 0) != (mention.value < 0) for n in numbers if n):
            continue  # "19" for a freezer read as -16 … -24: a sign lost, not a value to try
        value = _as_said(info, mention.value)
        goal[info.name] = value
        where[info.name] = mention.start
        claimed.update(range(mention.start, mention.end))
        reason = (
            f"not a value of {info.name} as read: {info.name} can be "
            f"{preview(values, quote=False)}; kept as said, for the words beside it name it"
        )
        outside.append(str(GoalParseError(text.span(mention.start, mention.end), reason)))


# words that make a number something other than the value asked for: a value refused, a limit
# or a comparison ("not 9", "no more than 9", "above 9"), or a count of events ("20 times")
_NOT_ASKED = frozenset(
    {"not", "no", "never", "don't", "dont", "without", "except", "instead", "than"}
    | {"above", "below", "over", "under", "beyond", "exceed", "exceeds", "past", "max"}
    | {"maximum", "least", "most", "until", "till", "since", "ago"}
)
_COUNTED_AFTER = frozenset({"times", "time", "x", "more", "less", "fewer", "ago", "or"})


def _not_a_value(text: Text, mention: Mention) -> bool:
    """The number is refused, bounds a value, compares or counts something (a word of
    :data:`_NOT_ASKED` in its clause before it, or a count word right after it)."""
    if text.word(mention.end) in _COUNTED_AFTER:
        return True
    for k in range(mention.start - 1, max(-1, mention.start - 1 - 2 * REACH), -1):
        word = text.word(k)
        if word in CLAUSE_ENDS or word in (",", "and", "then"):
            break
        if word in _NOT_ASKED:
            return True
    return False


def _nearest_setting(view: Model, text: Text, mention: Mention, goal: Goal) -> VarInfo | None:
    """The one open numeric setting whose own word is nearest the number (None: none within
    reach, or two at the same distance)."""
    best: list[tuple[int, VarInfo]] = []
    for info in view.infos.values():
        if info.role != "setting" or info.name in goal or not _numeric(info):
            continue
        own = own_concepts(info)
        distance = _distance(text, mention, own)
        if distance is not None:
            best.append((distance, info))
    if not best:
        return None
    best.sort(key=lambda b: b[0])
    if len(best) > 1 and best[1][0] == best[0][0]:
        return None
    return best[0][1]


def _distance(text: Text, mention: Mention, own: set[str]) -> int | None:
    """Tokens from the number to the nearest of ``own`` on either side, within the clause."""
    found: list[int] = []
    for direction, first in ((-1, mention.start - 1), (1, mention.end)):
        k = first
        for distance in range(1, REACH + 1):
            if not 0 <= k < len(text.tokens):
                break
            word = text.word(k)
            if word in CLAUSE_ENDS or word in (",", "and", "with", "then"):
                break
            if text.concepts[k] in own:
                found.append(distance)
                break
            if any(ch.isdigit() for ch in word):
                break  # another number stands between: the word is that number's
            k += direction
    return min(found) if found else None


def _numeric(info: VarInfo) -> bool:
    """A setting of numbers: a numeric one, or a list of values that are all numbers."""
    var = info.var
    if isinstance(var, NumericVariable):
        return True
    if isinstance(var, DiscreteVariable):
        return bool(info.values) and all(bare_number(v) is not None for v in info.values)
    return False


def _as_said(info: VarInfo, value: float) -> Any:
    """The number in the setting's own terms: a number, or text like its listed values."""
    number = int(value) if float(value).is_integer() else round(value, 3)
    if isinstance(info.var, NumericVariable):
        return number
    return str(number)
