"""A change said with its direction: "pitch down 1.5 %", "slow it down by ten percent".

A setting that runs either side of zero (a turntable's pitch -8 … +8 %, a trim, an offset)
takes a number said after a word of going down as below zero: people say the direction in
words rather than writing the minus sign. "Down to 3" is where it ends, not how far it moves,
so a "to" right before the number keeps it as said; a setting that cannot go below zero is
never touched.
"""

from __future__ import annotations

from typing import Any

from apbot.model.schema import DiscreteVariable, NumericVariable
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model, domain_values
from apbot.read.goal_vocab import STOP_WORDS

_DOWNWARD = frozenset({"down", "minus", "lower", "slower", "decrease", "reduce", "negative"})
_CLAUSE_ENDS = frozenset({",", ";", ".", "!", "?", "and", "then", "with", "but"})
_REACH = 5  # words back from the number: "slow it down by ten percent"
_BEHIND = frozenset({"behind", "lower", "down", "slower", "earlier", "back"})
"""Words after a number and its unit that say it counts down: "two hours behind", "two
semitones lower", "three notches back"."""
_FLAT = frozenset({"flat", "flats"})
"""A musical key's way of saying below zero ("two flats", "flat 2")."""
_KEEPS_MINUS = _DOWNWARD | _FLAT | {"drop", "dropped"}
_UPWARD = frozenset({"up", "plus", "raise", "higher", "increase", "ahead", "forward"})


def signed_changes(view: Model, text: Text, goal: Goal, where: dict[str, int]) -> None:
    """A positive number said after a word of going down becomes its negative, where the
    setting takes that negative."""
    for name, value in list(goal.items()):
        info = view.infos.get(name)
        if info is None or name not in where:
            continue
        if _unsaid_minus(view, text, goal, name, where[name]):
            continue
        if not isinstance(info.var, NumericVariable):
            value = _signed_choice(info.var, value)  # KEY ♭6 … ♯6 listed "-6" … "+6"
        if not isinstance(value, int | float) or value <= 0:
            continue
        start = where[name]
        if text.word(start - 1) == "to":
            continue  # "down to 3": the value it ends at
        if not (_said_before(text, start, _DOWNWARD) or _said_behind(text, start)):
            continue
        domain = domain_values(view, info, goal)
        negative = next((v for v in domain if _opposite(v, float(value))), None)
        if negative is not None:
            goal[name] = negative


def _unsaid_minus(view: Model, text: Text, goal: Goal, name: str, start: int) -> bool:
    """A listed negative choice ("-2" of "-3" … "+3") the sentence gave no minus for becomes
    its positive twin: the choices' names share the figure, so "key to 2" or "key to +2" matched
    both and the list's order picked the negative one. A minus sign, a word of going down
    before or after the number, or "flat(s)" (a key shown ♭2) keeps it."""
    info = view.infos[name]
    value = goal[name]
    if not isinstance(info.var, DiscreteVariable) or not str(value).startswith("-"):
        return False
    said = {text.word(start), text.word(start - 1), text.word(start + 1)}
    if said & _KEEPS_MINUS or _said_before(text, start, _KEEPS_MINUS):
        return False
    if _said_behind(text, start):
        return False
    twin = "+" + str(value)[1:]
    listed = [v for v in info.var.values or () if str(v) == twin]
    if not listed:
        return False
    goal[name] = listed[0]
    return True


def _opposite(v: Any, value: float) -> bool:
    try:
        return abs(float(v) + value) < 1e-9
    except (TypeError, ValueError):
        return False  # a word among the numbers (AUTO)


def _signed_choice(var: Any, value: Any) -> float | None:
    """A listed value written with a plus sign ("+2" of "-6" … "+6"), as its number."""
    if not isinstance(var, DiscreteVariable) or not str(value).startswith("+"):
        return None
    try:
        return float(str(value))
    except ValueError:
        return None


def _said_before(text: Text, start: int, words: frozenset[str]) -> bool:
    """One of ``words`` among the few words before the number, within its clause."""
    for k in range(start - 1, max(-1, start - 1 - _REACH), -1):
        word = text.word(k)
        if word in _CLAUSE_ENDS:
            return False
        if word in words:
            return True
    return False


def _said_behind(text: Text, start: int) -> bool:
    """The number's direction said right after it and its unit ("two hours behind the
    signal"); not a word of another phrase further on ("up two for the lower voice"), nor
    after a number said going up ("up 2 so the back row can sing")."""
    if _said_before(text, start, _UPWARD):
        return False
    for k in range(start + 1, min(len(text.tokens), start + 4)):
        word = text.word(k)
        if word in _BEHIND:
            return True
        if word in _CLAUSE_ENDS or word in STOP_WORDS:
            return False  # "for the lower voice": the direction of something else
    return False
