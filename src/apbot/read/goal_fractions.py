"""Fractions of a measure said in words: "half a cup", "three quarters of a scoop", "a quarter
cup", "five eighths of a cup".

A setting whose values are parts of a measure — written as fractions ("1/2", "3/8") or as their
names (HALF, QUARTER, THREE QUARTERS) — is asked for with the fraction in words before the
measure's noun. The number reader takes "half" for 0.5 of whatever follows (a duration, a
quantity), and a value named HALF is only one word of many; so the fraction is read here, before
the quantities, and given to the one open setting that has that part as a value.
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Any

from apbot.model.schema import DiscreteVariable
from apbot.model.values import NUMBER_WORDS
from apbot.read.goal_text import CLAUSE_ENDS, Text
from apbot.read.goal_values import parse_quantity
from apbot.read.goal_view import Goal, Model

# "a quarter", "three quarters": the article and the counting words one to seven
_NUMERATORS = {"a": 1, "an": 1} | {
    w: n for w, n in NUMBER_WORDS.items() if 1 <= n <= 7 and w not in ("single", "couple")
}
_PARTS = {
    "half": 2,
    "halves": 2,
    "third": 3,
    "thirds": 3,
    "quarter": 4,
    "quarters": 4,
    "fourth": 4,
    "fourths": 4,
    "sixth": 6,
    "sixths": 6,
    "eighth": 8,
    "eighths": 8,
}
_WHOLE = frozenset({"full", "whole"})  # "a full stop": the one whole measure beside its parts
_MANUAL_MEASURE = re.compile(r"\b\d\s*/\s*\d{1,2}\s+([a-z]{3,})\b")
"""A fraction the manual prints before a noun ("1/3 stop", "1/2 turn"): that noun is the
setting's measure, said in words ("a third of a stop", "half a turn")."""
_MEASURES = frozenset(
    {"cup", "cups", "scoop", "scoops", "spoon", "spoons", "spoonful", "spoonfuls"}
    | {"tablespoon", "tablespoons", "teaspoon", "teaspoons", "measure", "measures"}
    | {"portion", "portions", "serving", "servings", "bowl", "bowls", "glass", "glasses"}
    | {"jug", "jugs", "ladle", "ladles", "container", "tank", "tanks"}
)
"""Nouns of a measure a part is taken of; a part of an hour or of a load is something else."""


def fractions(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Give each fraction of a measure said in words to the one open setting with that part."""
    measures = _MEASURES | _manual_measures(view)
    k = 0
    while k < len(text.tokens):
        found = _fraction_at(text, k, measures)
        if found is None or any(j in claimed for j in range(k, found[1])):
            k += 1
            continue
        part, end = found
        owners = [
            (name, value)
            for name, info in view.infos.items()
            if name not in goal
            and info.role == "setting"
            and isinstance(info.var, DiscreteVariable)
            and _a_measure(info.var, info.values)
            for value in info.values
            if _part_of(info.var, value) == part or (part == 1 and str(value).strip() == "1")
        ]
        if len({name for name, _ in owners}) == 1:
            name, value = owners[0]
            goal[name] = value
            where[name] = k
            claimed.update(range(k, end))
        k = end


def _manual_measures(view: Model) -> frozenset[str]:
    """Nouns the manual counts in fractions ("1/3 stop"), beside the kitchen's measures."""
    found: set[str] = set()
    for line in view.manual_lines:
        found.update(m.casefold() for m in _MANUAL_MEASURE.findall(line.casefold()))
    return frozenset(w for w in found if parse_quantity(f"1 {w}") is None)


def _fraction_at(
    text: Text, k: int, measures: frozenset[str] = _MEASURES
) -> tuple[Fraction, int] | None:
    """The part said from token k and the end of the words (the measure's noun included)."""
    word = text.word(k)
    if word in _WHOLE and text.word(k - 1) in ("a", "one") and text.word(k + 1) in measures:
        return Fraction(1), k + 2  # "a full stop between the strips"
    if word in _PARTS:  # "half a cup", "quarter cup"
        part, j = Fraction(1, _PARTS[word]), k + 1
        if word.startswith("half") and text.word(k - 1) in ("and", "-"):
            return None  # "one and a half cups": a number, not a part
    elif word in _NUMERATORS and text.word(k + 1) in _PARTS:  # "a quarter", "five eighths"
        if word in ("a", "an") and text.word(k - 1) in ("and", "-"):
            return None  # "two and a half cups"
        part, j = Fraction(_NUMERATORS[word], _PARTS[text.word(k + 1)]), k + 2
    elif re.fullmatch(r"0?\.\d{1,3}", word):  # "half a cup" is spelled 0.5 cup before this
        part, j = Fraction(word).limit_denominator(8), k + 1
        if part != Fraction(word) or text.word(k - 1) in ("and", "-"):
            return None
    else:
        return None
    if part >= 1 or part <= 0:
        return None
    if text.word(j) == "-":
        j += 1  # "sixth-of-a-stop steps"
    if text.word(j) == "of":
        j += 1 + (text.word(j + 1) == "-")
    if text.word(j) in ("a", "an", "the", "one"):
        j += 1 + (text.word(j + 1) == "-")
    if text.word(j) not in measures or text.word(j) in CLAUSE_ENDS:
        return None
    if text.word(j + 1) in _CHANGES:
        return None  # "a third of a stop down from 8 s": a change of another setting, no step
    return part, j + 1


_CHANGES = frozenset({"down", "up", "more", "less", "longer", "shorter", "lower", "higher"})


def _a_measure(var: DiscreteVariable, values: list[Any]) -> bool:
    """The setting steps through parts of a measure (1/4, 1/2, 3/4 cup): two parts at least.
    A HALF beside FULL is a level of something else ("half load", "half power"), and "half a
    cup of detergent" says nothing about it."""
    return len({_part_of(var, value) for value in values} - {None}) >= 2


def _part_of(var: DiscreteVariable, value: Any) -> Fraction | None:
    """The part a value stands for: "3/8", "1/2", HALF, THREE_QUARTERS, or a show text "1/4"."""
    shown = var.show.get(value) if isinstance(var.show, dict) else None
    for said in (str(value), str(shown or "")):
        said = said.casefold().replace("_", " ").replace("-", " ").strip()
        match = re.fullmatch(r"(\d)\s*/\s*(\d{1,2})", said)
        if match and 0 < int(match[1]) < int(match[2]):
            return Fraction(int(match[1]), int(match[2]))
        words = said.split()
        if len(words) == 1 and words[0] in _PARTS:
            return Fraction(1, _PARTS[words[0]])
        if len(words) == 2 and words[0] in _NUMERATORS and words[1] in _PARTS:
            part = Fraction(_NUMERATORS[words[0]], _PARTS[words[1]])
            return part if part < 1 else None
    return None
