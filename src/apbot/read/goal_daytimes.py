"""Which time settings are times of day: a dial of the day's hours, a schedule's switch time.

A time of day ("at 7 pm") and a duration ("for 7 hours") are both h:mm; the parser must know
which a setting holds before it can give it either. Split from :mod:`apbot.read.goal_view`,
which asks these questions of every time setting it builds a view of.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from apbot.model.domain import AnyVariable
from apbot.model.schema import TimeVariable
from apbot.read.goal_values import magnitude, name_words
from apbot.read.goal_vocab import SPAN_ENDS, SPAN_STARTS, concept

if TYPE_CHECKING:
    from apbot.read.goal_view import VarInfo


def whole_day(info: VarInfo, wraps: bool = True) -> bool:
    """A time setting that wraps round a whole day (00:00 to 23:xx): a time of day. With
    ``wraps`` False, one that only spans it (a read belief seldom knows whether it wraps)."""
    var = info.var
    values = info.values
    if not isinstance(var, TimeVariable) or (wraps and not var.wrap) or not values:
        return False
    first, last = magnitude(values[0]), magnitude(values[-1])
    return first == 0 and last is not None and last >= 23 * 3600


_SWITCH_TIMES = (SPAN_STARTS | SPAN_ENDS) - {"end", "finish", "morning", "night"}


def switch_time(info: VarInfo) -> bool:
    """A time of day named for when something starts or stops (ON TIME, OFF, START, SUNRISE):
    a schedule the appliance keeps, not the time a started programme is done at."""
    return bool(set(name_words(f"{info.name} {info.var.label or ''}".casefold())) & _SWITCH_TIMES)


def day_dial(info: VarInfo) -> bool:
    """A whole-day time setting that stops short of 24:00 (00:00 to 23:xx): the hours of a day
    on a 24-hour dial, not a count of up to 24 hours (a 0-24 h timer ends at 24:00). One the
    model says starts at 00:00 is a timer counting from empty (a keep-warm of 0 to 23 hours):
    a time of day to feed or to start at starts at a time of day (07:00), or is not stated.
    Whether it wraps is not asked: a read belief (REGEN TIME 0:00-23:00, a mowing START
    0:00-23:30) seldom knows, and the day's last hour, not 24:00, already says a dial; but one
    that does not say it wraps and is named a timer (a TIMER, an OFF TIMER of 0:00-23:59)
    counts down a duration ("run for 10 hours")."""
    last = magnitude(info.values[-1]) if whole_day(info, wraps=False) else None
    if last is None or last >= 24 * 3600 or _starts_empty(info.var):
        return False
    return whole_day(info) or not _named_timer(info)


def _named_timer(info: VarInfo) -> bool:
    """The setting's own name or label calls it a timer: a countdown, not a time of day."""
    words = name_words(f"{info.name} {info.var.label or ''}".casefold())
    return any(concept(w) == concept("timer") for w in words)


def _starts_empty(var: AnyVariable) -> bool:
    """Whether the model states that a time setting starts at 00:00 (in each of its cases)."""
    cases = getattr(var, "cases", None) or {}
    starts = [getattr(c, "initial", None) for c in cases.values()] or [
        getattr(var, "initial", None)
    ]
    return all(s is not None and magnitude(s) == 0 for s in starts)
