"""Spellings rewritten before the instruction is tokenised: a compound the model writes as one
word said hyphenated, in camel case or as two words, fractions in words ("half a litre"), "half
power", and a number its speaker corrects at once ("speed 8 - no, make it seven": seven)."""

from __future__ import annotations

import itertools
import re

from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import stem

_HYPHEN_PAIR = re.compile(r"\b([A-Za-z]{2,})-([A-Za-z]{2,})\b")
# a brand's compound in camel case or as two words ("SmartStart", "smart start") for a model
# word written as one (SMARTSTART): the way a name is spaced is not part of it
_CAMEL_PAIR = re.compile(r"\b([A-Z]?[a-z]{2,})([A-Z][a-z]{2,})\b")
_WORD = re.compile(r"[A-Za-z]{2,}")
_PARTICLES = frozenset({"up", "down", "on", "off", "in", "out", "over", "back", "away"})


def joined_compounds(view: Model, instruction: str) -> str:
    """ "pre-infusion" for a PREINFUSION key: a hyphenated word the model writes as one."""
    words = {w for info in view.infos.values() for w in own_stems(info)}
    words |= {s for _var, _value, stems, _weight in view.phrases for s in stems}

    def join(match: re.Match[str]) -> str:
        whole = (match[1] + match[2]).casefold()  # one lower-case word: no camel case to split
        return whole if stem(whole) in words else match[0]

    text = _HYPHEN_PAIR.sub(join, _corrected(instruction))
    text = _joined_pairs(_CAMEL_PAIR.sub(join, text), words)
    text = _HALF_POWER.sub("50% power", text)
    return _fractions(text)


def _joined_pairs(text: str, words: set[str]) -> str:
    """Two words one space apart whose joining is a model word ("smart start"), joined. A verb
    and its particle ("start up", "warm up") are joined only before a word of the model ("the
    start up sound"): alone, "start up on speed 2" says to start, not the STARTUP setting."""
    found = list(_WORD.finditer(text))
    out, last = [], 0
    for n, (first, second) in enumerate(itertools.pairwise(found)):
        if first.start() < last or text[first.end() : second.start()] != " ":
            continue
        whole = (first[0] + second[0]).casefold()
        after = stem(found[n + 2][0].casefold()) if n + 2 < len(found) else ""
        if second[0].casefold() in _PARTICLES and after not in words:
            continue
        if stem(whole) in words:
            out += [text[last : first.start()], whole]
            last = second.end()
    return "".join(out) + text[last:]


_CORRECTED = re.compile(
    r"\b\d+(?:\.\d+)?\s*(?:\.\.\.|…|-|–|—|,)\s*(?:no|sorry)\b(?:,?\s*wait\b)?[,!]?\s*"
    r"(?:make (?:it|that)\s+)?(?=([a-z]+|\d))",
    re.IGNORECASE,
)


def _corrected(text: str) -> str:
    """A number taken back as soon as it is said ("at 190... no, make it 180", "speed 8 - no,
    make it seven"): only the correction is meant, so the first number goes."""
    from apbot.model.values import NUMBER_WORDS as WORDS

    def drop(match: re.Match[str]) -> str:
        said = match[1]
        return "" if said.isdigit() or said.lower() in WORDS else match[0]

    return _CORRECTED.sub(drop, text)


_UNIT_WORDS = r"(litres?|liters?|kilos?|kg|pounds?|lbs?|cups?|hours?|minutes?)"
_HALF_A = re.compile(rf"\bhalf an? {_UNIT_WORDS}\b", re.IGNORECASE)
_A_AND_A_HALF = re.compile(rf"\ban? {_UNIT_WORDS} and a half\b", re.IGNORECASE)
_AND_PART = re.compile(
    rf"\b(\d+|[a-z]+) and (a half|a quarter|three[- ]quarters?) {_UNIT_WORDS}\b", re.IGNORECASE
)
_FRACTIONS = {"a half": 0.5, "a quarter": 0.25}


def _fractions(text: str) -> str:
    """ "half a litre", "a kilo and a half", "three and three-quarter hours" as decimals."""
    from apbot.model.values import NUMBER_WORDS as WORDS

    text = _HALF_A.sub(lambda m: f"0.5 {m[1]}", text)
    text = _A_AND_A_HALF.sub(
        lambda m: m[0] if m[1].lower().startswith(("hour", "minute")) else f"1.5 {m[1]}", text
    )

    def part(m: re.Match[str]) -> str:
        whole = float(m[1]) if m[1].isdigit() else WORDS.get(m[1].lower())
        if whole is None:
            return m[0]
        fraction = _FRACTIONS.get(m[2].lower(), 0.75)
        return f"{whole + fraction:g} {m[3]}"

    return _AND_PART.sub(part, text)


_HALF_POWER = re.compile(r"\bhalf[- ]power\b", re.IGNORECASE)
