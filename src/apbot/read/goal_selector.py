"""An ON / AUTO / OFF selector: how an appliance switched by its own timer is powered.

A time switch, a lamp with a sunrise and a sunset, a socket timer has no power switch of its
own: one selector says whether it is on now, off now, or follows its programmed times (ON /
AUTO / OFF). People say the first two as they would of a power switch ("switch it on straight
away", "keep the lights off for now", "lights off manually"), and set the third by giving the
times ("the socket on at 5 pm", "from 7 am to 9.30 pm"): times programmed act only in AUTO.
"""

from __future__ import annotations

from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import DiscreteVariable
from apbot.read.goal_held import KEEPING
from apbot.read.goal_text import CLAUSE_ENDS, Text, negated_before
from apbot.read.goal_values import OFF_WORDS, ON_WORDS
from apbot.read.goal_view import Goal, Model
from apbot.read.goal_vocab import DETERMINERS, concept
from apbot.read.numbers import find_mentions

_VERBS = KEEPING | {"turn", "switch", "put", "power", "have", "get", "turned", "switched"}
_BETWEEN = frozenset({"the", "it", "them", "all", "my", "our"})
_STOPS = CLAUSE_ENDS | {",", "and", "then", "but", "so", "until", "till", "when", "with"}
# "on the timer", "on a 12 hour programme", "on the shelf": a place or a mode, not a state
_AUTO = frozenset(concept(w) for w in ("auto", "automatic", "timer", "programme", "program"))


def _selector(view: Model) -> tuple[str, Any, Any, Any] | None:
    """(name, on, off, auto) of the one setting whose values are on, off and an automatic
    one, on a model with no power switch (else that switch is the power)."""
    if any(info.role == "power" for info in view.infos.values()):
        return None
    found = []
    for name, info in view.infos.items():
        if info.role != "setting" or not isinstance(info.var, DiscreteVariable):
            continue
        values = info.values
        on = next((v for v in values if str(v).casefold() in ON_WORDS), None)
        off = next((v for v in values if str(v).casefold() in OFF_WORDS), None)
        rest = [v for v in values if v not in (on, off)]
        if on is None or off is None or len(rest) != 1 or concept(str(rest[0])) not in _AUTO:
            continue
        found.append((name, on, off, rest[0]))
    return found[0] if len(found) == 1 else None


def _state_said(view: Model, text: Text, k: int) -> bool:
    """ "switch it on", "keep the lights off", "Lights off" (a clause opening with the
    appliance's noun): the on / off at token k is said of the appliance itself."""
    j, named = k - 1, False
    while j >= 0 and (
        text.word(j) in _BETWEEN
        or (concept(text.word(j)) in view.appliance_words and text.word(j) not in _VERBS)
    ):  # a time SWITCH is called so, "switch" is still the verb
        named = named or text.word(j) != "the"
        j -= 1
    if not named:
        return False
    return text.word(j) in _VERBS or j < 0 or text.word(j) in CLAUSE_ENDS | {",", "-", "and"}


def _at_a_time(text: Text, k: int) -> bool:
    """A time of day said in the clause after the state ("on at 5 pm", "on from 7 am"): when
    it switches, a programmed time, not now."""
    end = k + 1
    while end < len(text.tokens) and text.word(end) not in _STOPS:
        end += 1
    return any(
        mention.kind == "clock"
        for mention in find_mentions(text.tokens[:end], skip=set(range(k + 1)))
    )


def on_auto_off(view: Model, text: Text, goal: Goal) -> None:
    """ON or OFF when the appliance is said on or off now; AUTO when the goal programmes a
    time it switches at (an ON TIME, a SUNRISE) and the selector does not start in AUTO."""
    selector = _selector(view)
    if selector is None or selector[0] in goal:
        return
    name, on, off, auto = selector
    for k, token in enumerate(text.tokens):
        if token.text == "on" and text.word(k + 1) in DETERMINERS:
            if concept(text.word(k + 2)) in _AUTO and _state_said(view, text, k):
                goal[name] = auto  # "keep the lights on the timer": its programmed times
                return
            continue  # "put it on the shelf": "on" a preposition
        if token.text in ("on", "off") and _state_said(view, text, k) and not _at_a_time(text, k):
            if negated_before(text, k, reach=5):
                continue  # "don't switch it on": no state asked of it
            goal[name] = on if token.text == "on" else off
            return
    domain = build_domain(view.infos[name].var)
    starts = domain.values[domain.initial]
    if starts != auto and any(view.infos[n].timing == "at" for n in goal if n in view.infos):
        goal[name] = auto
