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
        if text.word(k - 1) in ("never", "don't", "dont", "not"):
            continue  # "don't let it dim automatically": the choice is refused, not handed over
        verb = next(
            (j for j in range(k + 1, min(k + 5, len(text.stems))) if text.stems[j] in _CHOOSING),
            None,
        )
        if verb is None:
            _automatic_switch(view, text, k, goal, claimed)
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


_BY_ITSELF = (("by", "itself"), ("on", "its", "own"), ("automatically",), ("by", "themselves"))


def _automatic_switch(view: Model, text: Text, k: int, goal: Goal, claimed: set[int]) -> None:
    """ "let the projector correct the keystone by itself": any doing the appliance is let do on
    its own, of a thing an AUTO switch is named for (AUTO KEYSTONE), turns that switch on."""
    end = next(
        (j for j in range(k + 1, len(text.tokens)) if text.word(j) in CLAUSE_ENDS | {",", ";"}),
        len(text.tokens),
    )
    words = [text.word(j) for j in range(k + 1, end)]
    if not any(tuple(words[i : i + len(p)]) == p for p in _BY_ITSELF for i in range(len(words))):
        return
    autos = [
        info
        for info in view.infos.values()
        if info.role == "switch"
        and info.name not in goal
        and concept("auto") in {concept(s) for s in own_stems(info)}
    ]
    for j in range(k + 2, end):
        named = [info for info in autos if text.stems[j] in own_stems(info) - _AUTO_STEMS]
        if len(named) == 1 and j not in claimed and named[0].on is not None:
            goal[named[0].name] = named[0].on
            claimed.add(j)
            return


_AUTO_STEMS = frozenset(stem(w) for w in ("auto", "automatic"))


def _appliance_let(view: Model, text: Text, k: int) -> bool:
    """The one let choose at ``k`` is the appliance ("let it", "let the machine"), not the
    user: "let me set the speed myself" keeps the choice, so no AUTO is meant."""
    after = text.word(k + 1)
    if after == "the":
        after = text.word(k + 2)
    return after in ("it", "them") or concept(after) in view.appliance_words
