"""A state said with the time it should happen is that time's schedule, not the state now:
"open the curtains at 6:30 in the morning", "close at 7:45 pm every evening" set OPEN TIME /
CLOSE TIME; they do not open or close the curtains now. Only where the state's own word names
the time-of-day setting the time went to, in the same clause."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_view import Goal, Model, own_stems
from apbot.read.goal_vocab import stem

_TIME = re.compile(r"\d{1,2}[:.]\d\d\s*(?:[ap]\.?m\.?)?", re.IGNORECASE)


def _times_of_day(values: list[Any]) -> bool:
    """A list of times of day kept as text ("6:30 AM", "6:45 AM" …): a schedule too."""
    return bool(values) and all(_TIME.fullmatch(str(v).strip()) for v in values)


_BREAKS = CLAUSE_ENDS | {",", "and", "then", "but", ""}


def scheduled_states(view: Model, text: Text, goal: Goal, where: dict[str, int]) -> None:
    """Drop a state value (OPEN) whose word stands in the clause of the time given to the
    time-of-day setting that word names (OPEN TIME)."""
    for name in list(goal):
        info = view.infos.get(name)
        k = where.get(name)
        if info is None or k is None or not isinstance(info.var, DiscreteVariable):
            continue
        if info.role not in ("setting", "switch"):
            continue
        said = stem(str(goal[name]))
        if text.stems[k] == said and _said_when(text, goal, where, name, k):
            del goal[name]
            _state_elsewhere(view, text, goal, where, name)
            continue
        for other, at in where.items():
            timed = view.infos.get(other)
            if other == name or other not in goal or timed is None:
                continue
            if timed.timing != "at" and not _times_of_day(timed.values):
                continue
            if said not in own_stems(timed) or text.stems[k] != said:
                continue
            low, high = sorted((k, at))
            if not any(text.word(j) in _BREAKS for j in range(low + 1, high)):
                del goal[name]
                _state_elsewhere(view, text, goal, where, name)
                break


_TIME_UNITS = frozenset({"minute", "minutes", "min", "mins", "hour", "hours", "hr", "hrs"})


def _said_when(text: Text, goal: Goal, where: dict[str, int], name: str, k: int) -> bool:
    """ "close an hour after dusk", "open 20 minutes before sunrise": the state followed at
    once by a time given to another setting and "after" / "before" an event says when the
    state comes, not the state now."""
    for other, at in where.items():
        if other == name or other not in goal or not k < at <= k + 2:
            continue
        after = next((j for j in range(at + 1, at + 5) if text.word(j) in ("after", "before")), 0)
        if after and any(text.word(j) in _TIME_UNITS for j in range(at, after)):
            return True  # a length of time, then the event it is counted from
    return False


def _state_elsewhere(view: Model, text: Text, goal: Goal, where: dict[str, int], name: str) -> None:
    """The state said again in a clause of its own, with no time ("… opening at half past
    four, and close it right now"), is the state now."""
    timed = [at for other, at in where.items() if other in goal and other != name]
    for k, word_stem in enumerate(text.stems):
        value = next((v for v in view.infos[name].values if stem(str(v)) == word_stem), None)
        if value is None or any(_one_clause(text, k, at) for at in timed):
            continue
        goal[name], where[name] = value, k
        return


def _one_clause(text: Text, a: int, b: int) -> bool:
    low, high = sorted((a, b))
    return not any(text.word(j) in _BREAKS for j in range(low + 1, high))
