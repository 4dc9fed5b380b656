"""Words a setting is named by beyond its name's plain words (part of the goal parser's view).

A panel names a setting by an adjective ("BRIGHT", "THICK"), which people say as its noun
("full brightness", "the thickness"); and a belief may name a setting by a word the parser
otherwise skips as a key's verb ("HOLD" 0:00-2:00 at a kiln's peak): its own name still
names it ("no hold", "a 20-minute hold").
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from apbot.model.schema import NumericVariable, TimeVariable
from apbot.read.goal_values import name_words
from apbot.read.goal_vocab import STOP_WORDS, concept

if TYPE_CHECKING:
    from apbot.read.goal_text import Text
    from apbot.read.goal_view import VarInfo
    from apbot.read.numbers import Mention

TIMED_STOPS = frozenset({"hold", "pause", "entry"})
"""Key verbs that are as often the name of a time: a HOLD at temperature, a PAUSE between
bursts, an ENTRY delay."""


def add_nouns(info: VarInfo, text: str, weight: float = 0.9) -> None:
    """ "full brightness" for BRIGHT, "the thickness" for THICK: a setting a panel names by its
    adjective is said by the adjective's noun in -ness."""
    for word in name_words(text):
        plain = not word.endswith(("ness", "ing", "er", "ed", "s"))
        if plain and word.isalpha() and len(word) >= 4 and word not in STOP_WORDS:
            key = concept(f"{word}ness")
            info.vocab[key] = max(info.vocab.get(key, 0.0), weight)


def add_timed_stops(info: VarInfo, text: str) -> None:
    """A time or number setting that no word of its name names but a key verb of the kind
    that also names a time (HOLD, PAUSE, ENTRY) is named by it."""
    if info.vocab or not isinstance(info.var, (NumericVariable, TimeVariable)):
        return
    for word in name_words(text):
        if word in TIMED_STOPS:
            info.vocab[concept(word)] = 1.0


_ARTICLES = frozenset({"a", "an", "the", "its", "no", "your", "my", "this", "that"})


def held_at(info: VarInfo, text: Text, mention: Mention) -> bool:
    """ "hold at 70 for 30 minutes", "hold it at 62": a bare number after the key verb said as a
    verb and "at" is the level held there, not the length of the HOLD the verb names (a noun
    keeps it: "set the hold at 20")."""
    k = mention.start - 1
    if mention.kind != "number" or text.word(k) != "at":
        return False
    k -= 2 if text.word(k - 1) in ("it", "them") else 1
    word = text.word(k)
    return (
        word in TIMED_STOPS
        and info.vocab.get(concept(word), 0.0) > 0
        and text.word(k - 1) not in _ARTICLES
    )
