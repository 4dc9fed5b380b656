"""The words around a value name matched in an instruction that say it is not that value: the
appliance's own head noun ("an AGM battery"), a hyphenated compound ("air-dry", "medium-rare"),
another setting's name beside it ("low fan", "power level 8", "auto-close"), an on/off setting's
own name, a state the appliance reaches by itself.

Apart from ``goal_names`` because these are tests on a match's neighbours, which
``value_matches`` only consults; finding and ordering the matches stays there.
"""

from __future__ import annotations

import re

from apbot.read.goal_appliance_words import own_name
from apbot.read.goal_shortened import SYNONYM_STEMS
from apbot.read.goal_text import (
    CLAUSE_ENDS,
    CONNECTORS,
    NUMBER_WORDS,
    Text,
    near_vocab,
    phrase_here,
)
from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import HIGHEST, LOWEST, SCALES, SYNONYMS, stem
from apbot.read.numbers import COUNT_NOUNS


def _heads(text: Text, k: int, works_on: set[str], heads: set[str]) -> bool:
    """The word at k is what the appliance is named for ("an AGM battery" on a battery
    charger, "a relaxing auto massage" on a massage cushion with AUTO RELAX): the value's
    distinctive word before it says which kind of it."""
    if k + 1 < len(text.stems) and text.stems[k + 1] in works_on | heads:
        return False  # "the convection countertop oven": the appliance's own name goes on
    return k < len(text.tokens) and text.stems[k] in works_on and text.word(k).isalpha()


def _head_nouns(view: Model) -> set[str]:
    """The nouns naming the appliance itself, the last word of its name and of its category
    ("oven", "charger"): a word before them says what kind of appliance it is ("the
    convection oven"), not which programme to run."""
    found = set()
    for said in (own_name(view.model), view.model.appliance.category.replace("_", " ")):
        words = re.findall(r"[a-z]+", said.casefold())
        if words:
            found.add(stem(words[-1]))
    return found


def _compound_tail(text: Text, i: int) -> bool:
    """The word at i ends a hyphenated compound whose first part the match leaves out: "I'll
    air-dry them" is no DRY programme, the automatic "sterilise-and-dry" programme no DRY."""
    return text.word(i - 1) == "-" and text.word(i - 2).isalpha()


_SCALE_WORDS = frozenset(w for scale in SCALES for w in scale) | LOWEST | HIGHEST


_SCALE_WORDS |= frozenset(w for s in _SCALE_WORDS for w in SYNONYMS.get(s, ()))  # "slow-roast"


_LEVEL_NOUNS = frozenset(stem(w) for w in ("speed", "level", "power", "setting", "intensity"))


def _scale_head(text: Text, i: int, own: set[str]) -> bool:
    """A scale word that opens a hyphenated compound with a word off the scale ("a medium-rare
    steak", "low-fat milk") grades that word; it names no level ("medium-high" still does, and
    so does a compound with the setting's own word or a word for a level: "high-speed")."""
    if text.word(i) not in _SCALE_WORDS or text.word(i + 1) != "-":
        return False
    after = text.word(i + 2)
    if stem(after) in own | _LEVEL_NOUNS:
        return False
    return after.isalpha() and after not in _SCALE_WORDS


def _names_switch(view: Model, var: str, text: Text, i: int) -> bool:
    """The word at i is an on/off setting's own name, and nothing of ``var`` stands next to it."""
    if near_vocab(view.infos[var], text, i, i + 1, reach=2):
        return False
    for name, info in view.infos.items():
        own = own_stems(info)
        if name == var or info.role != "switch" or text.stems[i] not in own:
            continue
        said = text.word(i + 1) in ("on", "off") and text.word(i + 2) not in ("a", "an", "the")
        if said or phrase_here(text, i, own - {text.stems[i]}):
            return True  # "switch the light on" (not "AUTO on a half load")
    return False


def _qualifies_other(view: Model, var: str, text: Text, end: int) -> bool:
    """The value word stands right before another setting's own name, which a number or a
    superlative then sets ("manual speed 3", "the highest manual speed")."""
    if end >= len(text.tokens):
        return False
    others = [
        info
        for name, info in view.infos.items()
        if name != var and info.role == "setting" and text.stems[end] in own_stems(info)
    ]
    if not others:
        return False
    following = text.word(end + 1)
    before = text.word(end - 2)
    return following[:1].isdigit() or following in NUMBER_WORDS or before in LOWEST | HIGHEST


def _names_setting(view: Model, var: str, text: Text, i: int) -> bool:
    """The word at i is another setting's own name and one of that setting's values stands
    right beside it ("low fan", "fan on quiet", "high fan")."""
    if near_vocab(view.infos[var], text, i, i + 1, reach=1):
        return False  # "fan mode": the mode's own word is next to it
    for name, info in view.infos.items():
        if name == var or info.role != "setting" or text.stems[i] not in own_stems(info):
            continue
        values = {stem(str(v)) for v in info.values if str(v).isalpha()}
        said = values | {s for v in values for s in SYNONYM_STEMS.get(v, ())}
        after = i + 2 if text.word(i + 1) in ("on", "at", "to") else i + 1
        after += 1 if text.word(after) in ("the", "a") else 0
        for j in (i - 1, i + 1, after):
            if 0 <= j < len(text.tokens) and text.stems[j] in said:
                return True  # "low fan", "fan on quiet", "the soft texture" (SOFTER)
    return False


def _grades_other(view: Model, var: str, text: Text, i: int) -> bool:
    """A degree word right before another ordered setting's name grades that setting: "full
    volume", "the quietest volume", "a low-temperature alarm" ask for an end or a level of the
    volume or the alarm, not the HIGH / LOW of a sensitivity that merely shares the word."""
    from apbot.read.goal_ladders import ordered  # (goal_ladders reads value names too)

    if text.word(i) not in _SCALE_WORDS or near_vocab(view.infos[var], text, i, i + 1, reach=2):
        return False
    k = i + 2 if text.word(i + 1) == "-" else i + 1
    if k >= len(text.tokens):
        return False
    return any(
        name != var
        and info.role == "setting"
        and ordered(info)
        and info.vocab.get(text.concepts[k], 0.0) >= 0.8
        for name, info in view.infos.items()
    )


def _grades_named(view: Model, var: str, text: Text, i: int) -> bool:
    """ "set the low-temperature alarm as low as it goes": the comparison is said of the other
    ordered setting named just before it, when nothing of ``var`` stands there."""
    from apbot.read.goal_ladders import ordered

    if near_vocab(view.infos[var], text, i, i + 1, reach=3):
        return False
    return any(
        name != var
        and info.role == "setting"
        and ordered(info)
        and near_vocab(info, text, i - 1, i, reach=4) >= 0.2
        for name, info in view.infos.items()
    )


def _names_other(view: Model, var: str, text: Text, i: int, end: int) -> bool:
    """The words i..end name another variable, and a number or more of that variable's words
    follow ("power level 8" sets the level, not the POWER mode)."""
    keys = [text.concepts[k] for k in range(i, end) if text.word(k) not in CONNECTORS]
    others = [
        info
        for name, info in view.infos.items()
        if name != var and all(info.vocab.get(key, 0.0) >= 0.8 for key in keys)
    ]
    if not others:
        return False
    shared = {key for info in others for key in info.vocab}
    for k in (i - 1, end):
        key = text.concepts[k] if 0 <= k < len(text.concepts) else ""
        if key in view.infos[var].vocab and key not in shared:
            return False  # "temperature mode": the mode's own word is next to it
    k = end + 1 if text.word(end) == "(" else end
    following = text.word(k)
    if (following[:1].isdigit() or following in NUMBER_WORDS) and text.word(
        k + 1
    ) not in COUNT_NOUNS:
        return True
    key = text.concepts[k] if k < len(text.concepts) else ""
    return any(info.vocab.get(key, 0.0) for info in others)


def _tail_of_other_name(view: Model, var: str, text: Text, i: int) -> bool:
    """The word at i ends another setting's two-word name said just before it ("auto-close",
    "AUTO CLOSE"), a word that is not this variable's own."""
    k = i - 2 if text.word(i - 1) == "-" else i - 1
    if k < 0 or view.infos[var].vocab.get(text.concepts[k], 0.0) > 0:
        return False
    pair = (text.concepts[k], text.concepts[i])
    return any(
        name != var and all(info.vocab.get(key, 0.0) >= 0.8 for key in pair)
        for name, info in view.infos.items()
    )


_ITSELF = frozenset({"itself", "themselves", "automatically"})


def _by_itself(text: Text, end: int) -> bool:
    """A state the appliance is to reach on its own ("close itself after one minute", "close
    the door by itself after five minutes"): a setting for later, not the state to set now."""
    for k in range(end, end + 5):
        word = text.word(k)
        if word in CLAUSE_ENDS or word in ("", ",", "and"):
            return False
        if word in _ITSELF:
            return True
    return False
