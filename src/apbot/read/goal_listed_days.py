"""Weeks on a list of days: "four weeks" is the "28 d" of a fermentation's DAYS list.

A setting whose values are lengths in days ("1 d", "7 d", "28 d") takes weeks as a DAYS 1-45
number does (:func:`apbot.read.goal_periods.in_weeks`); a duration read that way goes to such
a list only ("I'm away for a week" sets no LIGHT HOURS to 168).
"""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import Text
from apbot.read.goal_values import parse_quantity
from apbot.read.goal_view import Goal, Model, VarInfo
from apbot.read.numbers import Mention


def listed_in_days(info: VarInfo) -> bool:
    """A list of values counted in days ("1 d", "7 d", "28 d": a fermentation's length), which
    takes "four weeks" as 28 days as a DAYS 1-45 number does."""
    if not isinstance(info.var, DiscreteVariable):
        return False
    quantities = [parse_quantity(str(v)) for v in info.values]
    days = [q for q in quantities if q is not None and q[1] == "time" and q[0] >= 86400]
    return len(days) >= 2 and len(days) == len([q for q in quantities if q is not None])


_WEEK_WORDS = frozenset({"week", "weeks", "wk", "wks", "fortnight", "fortnights"})


def weeks_elsewhere(
    view: Model,
    text: Text,
    mentions: list[Mention],
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
    outside: list[str] | None = None,
) -> list[Mention]:
    """Weeks read as days for a list of days ("28 d") go to such a list only: "I'm away for a
    week" gives no LIGHT HOURS 168, and is no quantity left for a later pass to place."""
    weeks = [m for m in mentions if m.kind == "duration" and text.word(m.end - 1) in _WEEK_WORDS]
    kept = {m.start for m in weeks}
    for name in [n for n, k in where.items() if n in goal and k in kept]:
        if listed_in_days(view.infos[name]):
            kept.discard(where[name])
        else:
            del goal[name]
            del where[name]
    dropped = [m for m in weeks if m.start in kept and not listed_to(view, goal, where, m)]
    for m in dropped:
        claimed.update(range(m.start, m.end))
        said = f"'{text.span(m.start, m.end)}'"
        if outside is not None:
            outside[:] = [o for o in outside if not o.startswith(said)]
    return [m for m in mentions if m not in dropped]


def listed_to(view: Model, goal: Goal, where: dict[str, int], mention: Mention) -> bool:
    return any(where.get(n) == mention.start and listed_in_days(view.infos[n]) for n in goal)
