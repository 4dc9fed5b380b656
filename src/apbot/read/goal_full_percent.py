"""A strength said at its end ("at full power", "the output at full") on an appliance that
counts its strength in percent, not in numbered levels: a light's BRIGHT 0-100 %, a fog
machine's output 10-100 %. The one open setting counted in percent up to 100 is it."""

from __future__ import annotations

from apbot.read.goal_ladders import ordered
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_values import bare_number
from apbot.read.goal_view import Goal, Model, domain_values

_ENDS = frozenset({"full", "maximum", "max", "minimum", "min"})
_STRENGTHS = frozenset({"power", "strength", "output"})
_CLOSERS = frozenset({",", "-", "and", "then", "but", "please", ""}) | CLAUSE_ENDS


def strength_at_end(text: Text, k: int) -> bool:
    """ "the output at full", "power at maximum": the strength named first, its end closing
    the clause (a noun after the end — "at full speed" — says what is at its end)."""
    return (
        text.word(k) in _ENDS
        and text.word(k - 1) == "at"
        and text.word(k - 2) in _STRENGTHS
        and text.word(k + 1) in _CLOSERS
    )


def percent_strength(view: Model, goal: Goal) -> tuple[float, str] | None:
    """The one open setting counted in percent whose top is 100 (none when two are)."""
    found = []
    for name, info in view.infos.items():
        if name in goal or info.role != "setting" or info.dimension != "ratio":
            continue
        if not ordered(info):
            continue
        said = [bare_number(v) for v in domain_values(view, info, goal)]
        numbers = [n for n in said if n is not None]
        if numbers and len(numbers) == len(said) and max(numbers) == 100:
            found.append(name)
    return (0.0, found[0]) if len(found) == 1 else None
