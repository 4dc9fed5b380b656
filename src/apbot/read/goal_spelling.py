"""Spellings rewritten before the instruction is tokenised: a hyphenated compound the model
writes as one word, fractions in words ("half a litre"), "half power"."""

from __future__ import annotations

import re

from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import stem

_HYPHEN_PAIR = re.compile(r"\b([A-Za-z]{2,})-([A-Za-z]{2,})\b")


def joined_compounds(view: Model, instruction: str) -> str:
    """ "pre-infusion" for a PREINFUSION key: a hyphenated word the model writes as one."""
    words = {w for info in view.infos.values() for w in own_stems(info)}
    words |= {s for _var, _value, stems, _weight in view.phrases for s in stems}

    def join(match: re.Match[str]) -> str:
        whole = match[1] + match[2]
        return whole if stem(whole) in words else match[0]

    text = _HALF_POWER.sub("50% power", _HYPHEN_PAIR.sub(join, instruction))
    return _fractions(text)


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
