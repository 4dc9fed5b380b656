"""A state said with the time it should happen is that time's schedule, not the state now:
"open the curtains at 6:30 in the morning", "close at 7:45 pm every evening" set OPEN TIME /
CLOSE TIME; they do not open or close the curtains now. Only where the state's own word names
the time-of-day setting the time went to, in the same clause."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_view import Goal, Model, own_stems
from apbot.read.goal_vocab import stem

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
        for other, at in where.items():
            timed = view.infos.get(other)
            if other == name or other not in goal or timed is None or timed.timing != "at":
                continue
            if said not in own_stems(timed) or text.stems[k] != said:
                continue
            low, high = sorted((k, at))
            if not any(text.word(j) in _BREAKS for j in range(low + 1, high)):
                del goal[name]
                break
