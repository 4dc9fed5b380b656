"""Settings the user named that the goal, as read, leaves out: a part of an honest claim.

"Brew a stout with a 90 minute boil and the recirculation pump on" read as the stout and the
boil has left the pump out; a robot that then says "done" has said something false. The goal
parser drops such a part when it cannot place its value; the setting's name is still in the
sentence. A word of the user's is counted as naming a setting the goal leaves out when

- it is one of the words a setting's own name or label is made of (a belief's shortened name
  counts: "recirculation" for RECIRC; two capitals count as a word: "TV" for a TV preset),
  and every other word of that name was said too (the "light" of "UV light" does not name a
  NIGHT LIGHT; a single letter of a name is said by a word it begins: "zero gravity" for
  ZERO G);
- no setting of the goal has it among its words or its values' words (the "water" of
  "extra water" names no other setting when EXTRA WATER is in the goal);
- it is not part of a quantity the user said ("two days"), nor beside a word of the goal's own
  ("the coffee preset temperature" describes the preset the goal holds), nor set aside
  ("ignoring the humidity target", "regardless of humidity", "at any fan speed") or left as
  it is ("don't change the fan speed", "leave the timer as it is", "the mode does not
  matter").

Only names are counted, never values: a value word ("hot", "dry") is too often said of the
food or the result to be a request of its own.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping
from typing import Any

from apbot.model.schema import ApplianceModel
from apbot.read.goal_values import kind_noun, name_words
from apbot.read.goal_view import Model, VarInfo, model_view, own_stems
from apbot.read.goal_vocab import HANDLING, NEGATIONS, STOP_WORDS, concept, stem
from apbot.read.number_tokens import Token, tokenize
from apbot.read.numbers import find_mentions

_ACRONYM = re.compile(r"\b[A-Z]{2}\b")
SHORTEST_NAME = 4  # a shortened name ("regen", "recirc") is at least this long
_ROLES = ("setting", "switch")
# words that set a setting aside rather than ask for it ("ignoring the humidity target",
# "regardless of humidity"), a couple of words before its name
_DISMISSING = frozenset(
    {"ignoring", "ignore", "regardless", "disregarding", "any", "whatever", "whichever"}
)
_DISMISSING_REACH = 3  # power and running are read from "start", "go", "switch on"
# a setting left as it is: a change said with a negation before its name ("don't change the
# fan speed", "without touching the timer"), or these words after it in its clause
_AS_IT_IS = frozenset({"unchanged", "alone", "matter", "matters"})
_CLAUSE_BREAKS = frozenset({".", ";", "!", "?", ",", "but", "and", "while"})


def unnamed_settings(
    belief: ApplianceModel, instruction: str, goal: Mapping[str, Any], manual: str = ""
) -> list[str]:
    """The words of ``instruction`` that name a setting of ``belief`` ``goal`` leaves out."""
    view = model_view(belief, manual)
    tokens = tokenize(instruction)
    quantities = {k for m in find_mentions(tokens) for k in range(m.start, m.end)}
    said = {stem(t.text) for t in tokens if t.text.isalpha()}
    held = _goal_words(view, goal)
    # two capitals are a name too ("TV position"), though too short for a word of it
    acronyms = {w.casefold() for w in _ACRONYM.findall(instruction)} - STOP_WORDS
    found: list[str] = []
    for k, token in enumerate(tokens):
        word = token.text
        if k in quantities or not (_content(word) or word in acronyms):
            continue
        key = concept(word)
        if _names(key, held) or key in view.appliance_words or kind_noun(key):
            continue
        if _beside_the_goal(tokens, k, held) or _dismissed(tokens, k) or _left(tokens, k):
            continue
        named = [
            name
            for name, info in view.infos.items()
            if info.role in _ROLES
            and _names(stem(word), own_stems(info))
            and _whole_name_said(info, said)
        ]
        if named and not any(name in goal for name in named):
            found.append(word)
    return found


def _content(word: str) -> bool:
    return word.isalpha() and len(word) >= 3 and word.casefold() not in STOP_WORDS


def _names(key: str, words: Collection[str]) -> bool:
    """``key`` is one of ``words``, or a longer form of one ("recirculation": "recirc")."""
    return key in words or any(len(w) >= SHORTEST_NAME and key.startswith(w) for w in words)


def _whole_name_said(info: VarInfo, said: set[str]) -> bool:
    """Every word of a setting's name (or of its label) was said, in its own or a longer
    form."""
    names = [info.name] + ([info.var.label] if info.var.label else [])
    return any(all(_said(w, said) for w in name_words(n) if w not in STOP_WORDS) for n in names)


def _said(word: str, said: set[str]) -> bool:
    """A word of a name was said, in its own or a longer form; a single letter of a name
    (the G of ZERO G) by a word it begins ("gravity")."""
    if len(word) == 1:
        return any(s.startswith(word.casefold()) for s in said)
    return any(_names(s, {stem(word)}) for s in said)


def _goal_words(view: Model, goal: Mapping[str, Any]) -> set[str]:
    """Every word the goal's settings are named by, and their values' words."""
    held: set[str] = set()
    for name in goal:
        if name in view.infos:
            held |= set(view.infos[name].vocab)
    for name, _value, stems, _weight in view.phrases:
        if name in goal:
            held |= set(stems) | {concept(s) for s in stems}
    return held


def _beside_the_goal(tokens: list[Token], k: int, held: set[str]) -> bool:
    """A neighbouring word is one of the goal's: the word describes that setting."""
    return any(
        0 <= j < len(tokens) and _content(tokens[j].text) and _names(concept(tokens[j].text), held)
        for j in (k - 1, k + 1)
    )


def _dismissed(tokens: list[Token], k: int) -> bool:
    """The user sets the named setting aside ("ignoring the humidity target")."""
    before = tokens[max(0, k - _DISMISSING_REACH) : k]
    return any(t.text.casefold() in _DISMISSING for t in before)


def _left(tokens: list[Token], k: int) -> bool:
    """The user leaves the named setting as it is ("don't change the fan speed", "leave the
    timer as it is", "the mode does not matter"): no request, so nothing left undone."""
    words = [t.text.casefold() for t in tokens]
    start = max((j + 1 for j in range(k) if words[j] in _CLAUSE_BREAKS), default=0)
    end = next((j for j in range(k + 1, len(words)) if words[j] in _CLAUSE_BREAKS), len(words))
    before, after = words[start:k], words[k + 1 : end]
    negated = [j for j, w in enumerate(before) if w in NEGATIONS]
    if negated and any(stem(w) in HANDLING for w in before[negated[0] + 1 :]):
        return True
    # "as it is" / "as is" ending the clause, not "on as it is cold"
    as_is = after[-3:] == ["as", "it", "is"] or after[-2:] == ["as", "is"]
    return as_is or any(w in _AS_IT_IS for w in after)
