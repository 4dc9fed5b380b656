"""A setting whose values are OFF, ON and more (a work light OFF / ON / FLASH): its name with
"on" or "off" said of it asks for that value.

Such a setting is no switch (it has a third state), and ON is no name of a value (every switch
has one), so neither :mod:`apbot.read.goal_switches` nor the value names read "the light on".
Yet a user says it exactly so: the thing named, its state right after it ("light on", "with the
torch off") or the switching verb's particle before it ("switch on the light").
"""

from __future__ import annotations

from typing import Any

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import Text
from apbot.read.goal_values import OFF_WORDS, ON_WORDS
from apbot.read.goal_view import Goal, Model, VarInfo

_TURNING = frozenset({"switch", "turn", "put", "flick", "switched", "turned"})


def _states(info: VarInfo) -> dict[str, Any] | None:
    """{"on": ON value, "off": OFF value} for a discrete setting that has both and more."""
    if info.role != "setting" or not isinstance(info.var, DiscreteVariable):
        return None
    values = info.values
    on = [v for v in values if str(v).casefold() == "on"]
    off = [v for v in values if str(v).casefold() in OFF_WORDS]
    if len(on) != 1 or len(off) != 1 or len(values) < 3:
        return None
    return {"on": on[0], "off": off[0]}


def on_values(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set such a setting to ON or OFF where its own word is said with that state."""
    for name, info in view.infos.items():
        states = _states(info)
        if states is None or name in goal:
            continue
        for k in range(len(text.tokens)):
            if k in claimed or info.vocab.get(text.concepts[k], 0.0) < 0.8:
                continue
            after = text.word(k + 1)
            before = text.word(k - 1)
            if before in ("the", "its", "my") and k >= 2:
                before, verb = text.word(k - 2), text.word(k - 3)
            else:
                verb = text.word(k - 2)
            state = None
            if after in ON_WORDS[:1] + OFF_WORDS[:1]:
                state = after  # "light on", "with the torch off"
            elif before in ("on", "off") and verb in _TURNING:
                state = before  # "switch on the torch"
            if state is None:
                continue
            goal[name] = states[state]
            where[name] = k
            claimed.add(k)
            break
