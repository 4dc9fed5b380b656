"""An ordinal before a setting's noun is that setting's number: "the second meal" is meal 2
(a feeder's M2), "the first slot" slot 1, "it's the third day" day 3 (an incubator's day
count). People count slots, meals and days by ordinals as often as by numbers; the rest of the
parser reads "meal 2" (a code by its number, a number beside its setting's word), so the
ordinal is written that way first. Only before a word of a setting that holds numbers or
numbered codes, and never after a number ("a 30 second rinse" keeps its seconds); "the
second level" is "level 2" wherever a setting counts in numbers, whatever it is named (a
SPEED 1-6 read as levels), since "level" names no setting but the kind of one."""

from __future__ import annotations

import re

from apbot.model.schema import DiscreteVariable, NumericVariable
from apbot.model.values import NUMBER_WORDS
from apbot.read.goal_fit import CODE
from apbot.read.goal_view import Model, VarInfo
from apbot.read.goal_vocab import concept

ORDINALS = {
    "first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5,
    "sixth": 6, "seventh": 7, "eighth": 8, "ninth": 9, "tenth": 10,
}  # fmt: skip
_ORDINAL_NOUN = re.compile(r"\b(" + "|".join(ORDINALS) + r")\s+([A-Za-z]+)\b", re.IGNORECASE)
_COUNTS = "|".join(w for w in NUMBER_WORDS if w not in ("a", "an", "single", "couple"))
_NUMBER_BEFORE = re.compile(rf"(\d|\b(?:{_COUNTS}))\W*$", re.IGNORECASE)
_NUMBER_AFTER = re.compile(rf"^\s*(?:\d|(?:{_COUNTS})\b)", re.IGNORECASE)
# an ordinal opening a clause before a verb and its object ("First program the timer …",
# "then first program it"): the order of the steps, not a setting's number
_CLAUSE_START = re.compile(r"(?:^|[.;:!?,]|\b(?:then|and|next))\s*$", re.IGNORECASE)
_OBJECT_AFTER = re.compile(r"^\s*(?:the|a|an|it|its|my|this|that|them)\b", re.IGNORECASE)


def ordinal_numbers(view: Model, instruction: str) -> str:
    """ "the second meal" as "the meal 2" where MEAL holds numbered values or a number."""
    nouns = {key for info in view.infos.values() if _numbered(info) for key in info.vocab if key}

    def number(match: re.Match[str]) -> str:
        before, after = instruction[: match.start()], instruction[match.end() :]
        if _NUMBER_BEFORE.search(before):
            return match[0]  # "30 second rinse", "one second": a unit of time
        if _NUMBER_AFTER.match(after):
            return match[0]  # "first tray 2, then …": the number is said; the ordinal orders
        if _CLAUSE_START.search(before) and _OBJECT_AFTER.match(after):
            return match[0]  # "First program the delay": a step's order, the noun a verb
        if match[2].casefold() == "level" and any(map(_numbered, view.infos.values())):
            return f"{match[2]} {ORDINALS[match[1].casefold()]}"  # "the second level": level 2
        if concept(match[2].casefold()) not in nouns and not _code_initial(view, match[2]):
            return match[0]
        return f"{match[2]} {ORDINALS[match[1].casefold()]}"

    return _ORDINAL_NOUN.sub(number, instruction)


def _code_initial(view: Model, noun: str) -> bool:
    """ "the second timer" for T2 of T1 / T2 / T3: a noun the manual uses, whose first letter
    is the one letter every numbered code of a setting shares (a code's letter abbreviates its
    noun), and that no setting is named by ("the second time" is no T2)."""
    word = noun.casefold()
    if len(word) < 4 or word not in view.manual_words or not word.isalpha():
        return False
    if any(concept(word) in info.vocab for info in view.infos.values()):
        return False
    for info in view.infos.values():
        if not isinstance(info.var, DiscreteVariable) or not _numbered(info):
            continue
        letters = {_LETTER.sub("", str(v)).casefold() for v in info.values}
        if letters == {word[0]} and not _one_codes_name(view, word):
            return True
    return False


def _one_codes_name(view: Model, word: str) -> bool:
    """The manual gives the noun as one code's own name ("P2 pizza", "P2: Pizza", "| P2 |
    Pizza"): "the second pizza" counts pizzas, it is no P2 (the family's noun, "countdown",
    stands before its codes: "the countdown C1 or C2")."""
    named = re.compile(rf"(?<![a-z0-9]){word[0]}\d{{1,2}}[\s:=|(\-–—]*{word}s?\b")
    return any(named.search(line) for line in view.manual_lines)


_LETTER = re.compile(r"[- ]?\d+$")
_WORD_NUMBER = re.compile(r"[A-Za-z]+[- ]?\d{1,2}")  # "user 1", "slot-2": a word and its number


def _numbered(info: VarInfo) -> bool:
    """A setting of numbers (a day count) or of values coded with numbers (M1 … M4)."""
    if info.role != "setting":
        return False
    if isinstance(info.var, NumericVariable):
        return info.dimension is None
    if isinstance(info.var, DiscreteVariable):
        values = [str(v) for v in info.values if str(v).casefold() != "off"]  # OFF, L1 … L5
        counted = [
            v for v in values if CODE.fullmatch(v) or v.isdigit() or _WORD_NUMBER.fullmatch(v)
        ]
        # one named value past the counted ones (PER 1 … PER 4, OT) still leaves them counted
        return len(values) >= 2 and len(counted) >= len(values) - (len(values) >= 4)
    return False
