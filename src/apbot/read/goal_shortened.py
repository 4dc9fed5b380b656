"""Words a panel prints shorter than people say them: a stem shorter than the panel's word (BUZZ
for buzzer), a compound's head (POT for teapot), three-letter codes (SLO, FST, GRN), an adverb
of a value's adjective (gently, slowly), a word cut from a synonym's (split from ``goal_names``,
which matches value names in the instruction)."""

from __future__ import annotations

import re
from typing import Any

from apbot.read.goal_text import NUMBER_WORDS, Text
from apbot.read.goal_view import Model, VarInfo, name_words, own_stems, phrase_words
from apbot.read.goal_vocab import (
    DETERMINERS,
    HIGHEST,
    LOWEST,
    STOP_WORDS,
    SYNONYMS,
    concept,
    cut_short,
    stem,
)


def raw_words(value: Any, stems: tuple[str, ...]) -> tuple[str, ...]:
    """The value's own words as the panel prints them, one per stem (or none): a stem may
    cut the word shorter than the panel does ("buzz" stems to "buz")."""
    words = tuple(w.casefold() for w in phrase_words(str(value)))
    return words if len(words) == len(stems) else ()


def cut_short_word(short: str, stemmed: str, word: str) -> bool:
    """The panel's word of at least four letters, longer than its stem, starts the user's
    word and is most of it ("buzzer" for BUZZ): the stem alone is too short to be trusted
    as a prefix ("buz")."""
    return (
        len(short) >= 4
        and short != stemmed
        and len(word) <= len(short) + 4
        and cut_short(short, word)
        and word not in LOWEST | HIGHEST
    )


def compound_head(short: str, word: str, known: frozenset[str]) -> bool:
    """The user's word is a compound ending in the value's word, its first part a word of
    the manual of three letters or more ("teapot" for POT where the manual speaks of tea):
    the value is the compound's head noun. A word that merely ends in the same letters
    ("spot", "depot", "hotspot") has no such first part."""
    rest = word[: len(word) - len(short)]
    return (
        len(short) >= 3
        and short.isalpha()
        and word.endswith(short)
        and len(rest) >= 3
        and rest in known
        and rest not in STOP_WORDS
        and rest not in NUMBER_WORDS
    )


# prepositions saying where the appliance or a thing stands: "on the countertop", "by the door"
_PLACED = frozenset({"on", "onto", "at", "by", "near", "beside", "under", "against", "behind"})


def said_as_place(text: Text, k: int) -> bool:
    """The compound at ``k`` is where something is put ("leave it on the countertop"), not the
    thing filled or chosen ("fill the teapot"): a compound said so names no value's head noun."""
    j = k - 1
    while j >= 0 and text.word(j) in DETERMINERS:
        j -= 1
    return j >= 0 and text.word(j) in _PLACED


# "was in the freezer", "had been inside the oven": where a thing stood before, a remark
_PAST = frozenset({"was", "were", "been"})
_INSIDE = frozenset({"in", "inside"})


def said_as_past_place(text: Text, k: int) -> bool:
    """The word at ``k`` says where something was ("the bowl was in the freezer"): a past-tense
    remark on the load names no value (FREEZE), unlike a request ("put it on freeze")."""
    j = k - 1
    while j >= 0 and text.word(j) in DETERMINERS:
        j -= 1
    return j >= 1 and text.word(j) in _INSIDE and text.word(j - 1) in _PAST


def adverb_of(text: Text, k: int, target: str, coded: bool, known: frozenset[str]) -> bool:
    """Token k is the adverb of the value's adjective: "gently" of GENTLE (the adjective's
    final e dropped before -ly), or "slowly" of a panel code that cuts "slow" short (SLO), a
    word the manual uses, as for the code itself (``goal_names._match_at``). An adverb whose
    adjective is another word ("automatically") names no value, nor does one that opens a clause
    before a comma: "Finally, …", "Normally, …" comment on the sentence, not on how the job is
    done."""
    word = text.word(k)
    if not word.endswith("ly") or len(word) <= 5:
        return False
    if text.word(k + 1) == "," and (k == 0 or text.word(k - 1) in (".", ";", "!", ",")):
        return False
    if stem(word[:-1] + "e") == target and word[-3] not in _VOWELS:
        return True
    adjective = word[:-2]
    return coded and (not known or adjective in known) and display_abbreviation(target, adjective)


_VOWELS = frozenset("aeiouy")


def panel_code(value: Any) -> bool:
    """A value written as three letters ("SLO", "GRN"): a code that may cut a word short (not
    a longer word whose stem has three letters: "free", "time")."""
    return isinstance(value, str) and len(value) == 3 and value.isalpha()


def display_abbreviation(code: str, word: str) -> bool:
    """A three-letter panel code is ``word`` cut short: its first three letters ("SLO" for slow,
    "MAN" for manual, of a word at most twice as long) or its consonants ("FST" for fast, "GRN"
    for green, "WHT" for white). A time unit, a number, an ordinal or a key's verb is never
    cut short so: "a minute" is no MIN, "midnight" no MID, "second" no SEC, "press" no PRE. Nor
    is the code's doer ("fryer" for FRY, "the air fryer": the appliance, not its AIR FRY), which
    ``goal_names._match_at`` reads before as the code's word and "-er"."""
    if len(code) != 3 or not code.isalpha() or len(word) <= 3 or word[0] != code[0]:
        return False
    if word == code + "er":
        return False
    if word in NUMBER_WORDS or word in _NOT_CUT or word in STOP_WORDS or word.endswith("ly"):
        return False
    if word.startswith(code):
        return len(word) <= 2 * len(code)
    consonants = word[0] + "".join(c for c in word[1:] if c not in _VOWELS)
    squeezed = re.sub(r"(.)\1+", r"\1", consonants)
    return squeezed == code


_NOT_CUT = frozenset(
    {"minute", "minutes", "second", "seconds", "hour", "hours", "month", "months", "week", "weeks"}
    | {"midday", "maxi", "mini", "lower", "higher", "highest", "lowest", "topped"}
)


def abbreviated_synonym(short: str, word: str) -> bool:
    """``short`` cuts one word of a synonym group short ("ster" of sterilise) that ``word``
    belongs to ("steam")."""
    return any(
        key.startswith(short) and key != short and word in others
        for key, others in SYNONYM_STEMS.items()
    )


SYNONYM_STEMS: dict[str, frozenset[str]] = {
    stem(word): frozenset(stem(w) for w in others) for word, others in SYNONYMS.items()
}


_PLACES = frozenset({"head", "tail", "side", "front", "rear", "top", "bottom", "under"})
"""First parts of a compound that say where a thing sits, not what kind it is."""


def compound_of_name(view: Model, info: VarInfo, word: str) -> bool:
    """The user's word is a compound whose head is the switch's one-word name ("headlight"
    for LIGHT, "nightlight" for LAMP) and which the manual itself uses for it, or whose first
    part only says where the thing sits ("the headlights" of a chair whose manual says only
    "lights"; a "sunlamp" is another lamp): what the panel labels by its head noun, the user
    calls by the whole compound. Not a word another setting is named by ("backlight" beside
    BACKLIGHT)."""
    own = own_stems(info)
    if len(own) != 1:
        return False
    names = [w.casefold() for w in name_words(f"{info.name} {info.var.label or ''}")]
    short = next((w for w in names if stem(w) in own), "")
    rest = word[: len(word) - len(short)]
    if len(short) < 4 or not word.endswith(short) or len(rest) < 3 or not rest.isalpha():
        return False
    if word not in view.manual_words and rest not in _PLACES:
        return False  # "sunlamp" for a taillamp: another kind of thing, unless the manual says it
    return not any(
        concept(word) in other.vocab or stem(word) in own_stems(other)
        for other in view.infos.values()
        if other is not info
    )
