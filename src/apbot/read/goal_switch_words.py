"""Another switch's name said around a switch's word: "super freeze" beside SUPER COOL is SUPER
FREEZE, "the startup sound" beside a MUTE (whose group "sound" is) STARTUP TONE. A word a
switch shares with another names the one whose words stand with it."""

from __future__ import annotations

from apbot.read.goal_shortened import display_abbreviation
from apbot.read.goal_text import NUMBER_WORDS, Text
from apbot.read.goal_values import OFF_WORDS, ON_WORDS, name_words
from apbot.read.goal_view import Model, VarInfo, own_stems
from apbot.read.goal_vocab import STOP_WORDS, stem


def tail_of_anothers(view: Model, info: VarInfo, text: Text, k: int) -> bool:
    """A synonym of this switch's word right after another switch's own word names that
    other one: "the startup sound off" is STARTUP TONE, no MUTE (whose group "sound" is)."""
    if k == 0 or text.stems[k] in own_stems(info) or text.word(k - 1) in STOP_WORDS:
        return False
    before = text.stems[k - 1]
    return before not in own_stems(info) and any(
        other is not info and other.role == "switch" and before in own_stems(other)
        for other in view.infos.values()
    )


def another_switchs_phrase(view: Model, info: VarInfo, text: Text, k: int) -> bool:
    """The word at k and the word after it are both another switch's own words, and the
    second is not this one's: the two name that switch ("super freeze" beside SUPER COOL)."""
    here, after = text.concepts[k], text.concepts[k + 1] if k + 1 < len(text.concepts) else ""
    if not after or info.vocab.get(after, 0.0) > 0:
        return False
    word = text.word(k + 1)
    return any(
        other is not info
        and other.role == "switch"
        and other.vocab.get(here, 0.0) >= 0.8
        and (other.vocab.get(after, 0.0) >= 0.8 or _code_of(other, info, word))
        for other in view.infos.values()
    )


def _code_of(other: VarInfo, info: VarInfo, word: str) -> bool:
    """The word is spelled out from a panel code of the other switch's own name that this
    one's lacks: "super freeze" for SUPER FRZ beside SUPER (COOL)."""
    mine = own_stems(info)
    return any(
        display_abbreviation(code, word)
        for code in name_words(other.name)
        if stem(code) not in mine
    )


def whole_name_switched(view: Model, info: VarInfo, text: Text, k: int) -> bool:
    """The switch's whole name is the one word said, and its state follows it ("the output
    on" for an OUTPUT switch): the switch is named, though the word is a synonym of a general
    kind ("output" of power) that alone never names a setting."""
    names = [stem(w) for w in name_words(info.name)]
    if names != [text.stems[k]] or text.word(k + 1) not in ON_WORDS + OFF_WORDS:
        return False
    return not any(
        other is not info and text.stems[k] in {stem(w) for w in name_words(other.name)}
        for other in view.infos.values()
    )


_STATE_VERBS = frozenset({"switched", "turned", "set", "kept", "left", "put"})


def state_said_after(text: Text, k: int) -> bool:
    """The word at k is followed by its state: "the alert off", "the alert switched on". A
    number after the state word makes it a preposition ("the timer on 30 minutes")."""
    j = k + 1
    if text.word(j) in _STATE_VERBS:
        j += 1
    if text.word(j) not in ON_WORDS + OFF_WORDS:
        return False
    after = text.word(j + 1)
    return not (after[:1].isdigit() or after in NUMBER_WORDS)


def qualified_by_anothers(view: Model, info: VarInfo, text: Text, k: int) -> bool:
    """This switch's own word right after another switch's own word, in a phrase the manual
    prints, names that other one: "the hazard lights" (manual: "hazard lights") are the
    HAZARD switch, not LIGHTS; "hazard warning lights" too, one word between."""
    if text.stems[k] not in own_stems(info):
        return False
    for j in (k - 1, k - 2):
        if j < 0 or not text.word(j).isalpha() or text.word(j) in STOP_WORDS:
            return False
        if text.stems[j] in own_stems(info):
            return False
        if any(
            other is not info and other.role == "switch" and text.stems[j] in own_stems(other)
            for other in view.infos.values()
        ):
            phrase = " ".join(text.word(x) for x in range(j, k + 1))
            return any(phrase in line for line in view.manual_lines)
    return False
