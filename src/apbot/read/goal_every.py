"""How often, said the way people say it: "every other day" is every 2 days, "every third day"
every 3 days, "once a week" every 7 days, "turning every hour" every 1 hour. A panel's interval
is a number of hours or days ("EVERY 2D", a turning interval of 1-12 h), and the rest of the
parser reads "every 2 days" (a value holding that quantity, or a number beside its unit), so the
phrase is written that way first. A phrase a value of the model is literally named by ("every
day", "every week") is left as it is: that value's own name reads it. Only on a panel with a
setting of how often (named for its interval or frequency, with values said "every …", or
shown as counts of days or hours, "W 2d", "d3"): on
another, "I wash every day" is a habit, not a 24-hour delay.
"""

from __future__ import annotations

import re

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_ordinals import ORDINALS
from apbot.read.goal_values import parse_quantity, shown_count
from apbot.read.goal_view import Model, VarInfo

# "every other day", "every third day": the ordinals that count days apart ("first" does not)
_ORDINALS = {"other": 2, **{word: n for word, n in ORDINALS.items() if n >= 2}}
_UNITS = r"(minute|hour|day|week)"
_ONCE = re.compile(rf"\bonce\s+(?:a|an|per|every)\s+{_UNITS}\b", re.IGNORECASE)
_EVERY = re.compile(
    rf"\bevery\s+(?:({'|'.join(_ORDINALS)})\s+)?{_UNITS}\b(?!\s*[-/]?\s*(?:long|old))",
    re.IGNORECASE,
)


_DAY = 86400
_PERIOD_WORDS = frozenset({"interval", "intervals", "often", "frequency", "every", "period"})


def _shows_counts(info: VarInfo) -> bool:
    """A list setting whose values the display shows as counts of days or hours ("W 2d")."""
    show = info.var.show if isinstance(info.var.show, dict) else {}
    counted = [t for t in show.values() if isinstance(t, str) and shown_count(t) is not None]
    return len(counted) >= 2


def _has_period(view: Model, named: set[str]) -> bool:
    """A setting of how often: its name or label says an interval ("TURN INTERVAL", "HOW
    OFTEN"), or its values are said "every …" ("every 2 days") or counted in whole days
    ("1 d", "3 d": a panel's choices of days are how often, a stay of days is a number)."""
    if any(value.startswith(("every ", "once ")) for value in named):
        return True
    if any(_shows_counts(info) for info in view.infos.values() if info.role == "setting"):
        return True
    days = [q for value in named if (q := parse_quantity(value)) and q[1] == "time"]
    if len(days) >= 2 and all(q[0] >= _DAY and q[0] % _DAY == 0 for q in days):
        return True
    return any(
        _PERIOD_WORDS & set(re.findall(r"[a-z]+", f"{name} {info.var.label or ''}".casefold()))
        for name, info in view.infos.items()
        if info.role == "setting"
    )


def every_periods(view: Model, instruction: str) -> str:
    """Rewrite "every other day", "every third day", "once a week", "every hour" with a number
    ("every 2 days", "every 3 days", "every 7 days", "every 1 hour")."""
    named = {
        str(value).casefold()
        for info in view.infos.values()
        if isinstance(info.var, DiscreteVariable)
        for value in info.values
    }
    if not _has_period(view, named):
        return instruction
    instruction = _ONCE.sub(lambda m: f"every {m[1]}", instruction)

    def number(match: re.Match[str]) -> str:
        if any(match[0].casefold() in value for value in named):
            return match[0]
        count = _ORDINALS[match[1].casefold()] if match[1] else 1
        unit = match[2].casefold()
        if unit == "week":
            count, unit = count * 7, "day"
        return f"every {count} {unit}{'s' if count > 1 else ''}"

    return _EVERY.sub(number, instruction)
