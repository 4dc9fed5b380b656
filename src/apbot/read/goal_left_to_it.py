"""A choice left to the appliance: "let the machine pick the ramp by itself", "let it choose
the fan speed" name the setting's AUTO value — the user hands that choice over, which is what
an AUTO value of a setting is for."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_view import Goal, Model, domain_values, own_stems
from apbot.read.goal_vocab import concept, stem

_CHOOSING = frozenset(stem(w) for w in ("pick", "choose", "decide", "select", "set", "adjust"))
_AUTO = frozenset({"auto", "automatic"})


def left_to_it(view: Model, text: Text, goal: Goal, claimed: set[int]) -> None:
    """Set a setting to its AUTO value when the user lets the appliance choose it."""
    for k in range(len(text.tokens)):
        if text.word(k) != "let" or not _appliance_let(view, text, k):
            continue
        verb = next(
            (j for j in range(k + 1, min(k + 5, len(text.stems))) if text.stems[j] in _CHOOSING),
            None,
        )
        if verb is None:
            continue
        for j in range(verb + 1, min(verb + 5, len(text.tokens))):
            if text.word(j) in CLAUSE_ENDS or text.word(j) == ",":
                break
            for name, info in view.infos.items():
                if name in goal or info.role != "setting" or j in claimed:
                    continue
                if not isinstance(info.var, DiscreteVariable) or text.stems[j] not in own_stems(
                    info
                ):
                    continue
                autos = [v for v in domain_values(view, info, goal) if str(v).casefold() in _AUTO]
                if len(autos) == 1:
                    goal[name] = autos[0]
                    claimed.add(j)


def _appliance_let(view: Model, text: Text, k: int) -> bool:
    """The one let choose at ``k`` is the appliance ("let it", "let the machine"), not the
    user: "let me set the speed myself" keeps the choice, so no AUTO is meant."""
    after = text.word(k + 1)
    if after == "the":
        after = text.word(k + 2)
    return after in ("it", "them") or concept(after) in view.appliance_words
