"""A value word that is also the name of a numbered setting, said as that setting's owner.

A scoreboard's possession can be HOME or GUEST, and its scores are HOME and GUEST too: "Home
has seven points", "Home twenty, guests eighteen", "the guests lead eleven to nine" say whose
score, not who has the ball. The word is read as the value only where the value's own setting
is named within a few words ("the home side has the possession arrow") or the value is given
to it ("possession to the guests", "the arrow to the home team": "to" before it); elsewhere,
when its clause holds a number, it names the numbered setting. Only for a setting two or more
of whose values so name numbered settings (a "dry" programme beside a DRY TIME stays a value).
"""

from __future__ import annotations

from typing import Any

from apbot.model.schema import NumericVariable
from apbot.model.values import words_to_number
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import stem

_NEAR = 4
_CLAUSE_BREAKS = CLAUSE_ENDS | {",", ":", "and"}


def _clause(text: Text, k: int) -> range:
    start, end = k, k + 1
    while start > 0 and text.word(start - 1) not in _CLAUSE_BREAKS:
        start -= 1
    while end < len(text.tokens) and text.word(end) not in _CLAUSE_BREAKS:
        end += 1
    return range(start, end)


def _number_in(text: Text, where: range, skip: int) -> bool:
    """A number said in the clause (not "a" / "an")."""
    return any(
        j != skip
        and text.word(j) not in ("a", "an")
        and (text.word(j)[:1].isdigit() or words_to_number(text.word(j)) is not None)
        for j in where
    )


def owner_words(view: Model, text: Text, matches: list[Any]) -> list[Any]:
    """The value matches, less those whose word names a numbered setting given a number."""
    numbered = {
        stem: name
        for name, info in view.infos.items()
        if info.role == "setting" and isinstance(info.var, NumericVariable)
        for stem in own_stems(info)
    }
    owners = {  # settings whose values name two or more numbered settings: HOME / GUEST
        name
        for name, info in view.infos.items()
        if len({numbered.get(stem(str(v))) for v in info.values} - {None}) >= 2
    }
    kept = []
    for match in matches:
        if match.var not in owners:
            kept.append(match)
            continue
        one = match.end - match.start == 1
        other = numbered.get(text.stems[match.start]) if one else None
        if other is None or other == match.var:
            kept.append(match)
            continue
        own = view.infos[match.var].vocab
        k = match.start
        near = range(max(0, k - _NEAR), min(len(text.tokens), k + _NEAR + 1))
        named = any(own.get(text.concepts[j], 0.0) >= 0.8 for j in near if j != k)
        given = "to" in (text.word(k - 1), text.word(k - 2))
        if named or given or not _number_in(text, _clause(text, k), k):
            kept.append(match)
    return kept
