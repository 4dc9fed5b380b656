"""Light said in stops and in fractions of full power, as a flash or a lamp counts it.

A flash's manual power is a fraction of full power (1/1 … 1/128, with "+0.3" / "+0.7" for a
third and two thirds of a stop above), and its exposure compensation is a number of stops
written in thirds as decimals (-1.3, +0.7). People say both in words: "one-sixteenth power plus
a third of a stop", "an eighth of full power", "minus one and a third stops", "bring it down by
two-thirds of a stop", "a full stop more than metered". The words are rewritten as the value
the setting writes — only where a setting has exactly that value, so a model without such a
scale reads the sentence as before.
"""

from __future__ import annotations

import re
from fractions import Fraction

from apbot.model.values import NUMBER_WORDS
from apbot.read.goal_view import Model

_PARTS = {
    "half": 2,
    "quarter": 4,
    "fourth": 4,
    "eighth": 8,
    "sixteenth": 16,
    "thirty-second": 32,
    "sixty-fourth": 64,
    "hundred-and-twenty-eighth": 128,
    "hundred-twenty-eighth": 128,
}
_PART = (
    r"(?:one|a|an)?[\s-]*("
    + "|".join(p.replace("-", r"[\s-]+") for p in sorted(_PARTS, key=len, reverse=True))
    + r")"
)
_THIRDS = r"(?:\s*(?:plus|and|\+)\s+(a|one|two)[\s-]+thirds?(?:\s+of\s+a\s+stop)?)?"
_POWER_PART = re.compile(
    rf"\b{_PART}(?:\s+of(?:\s+(?:the|its))?\s+(?:full|maximum|max)(?:\s+(?:power|output))?"
    rf"|\s+(?:power|output)){_THIRDS}",
    re.IGNORECASE,
)
_COUNT = r"(\d|one|two|three|a(?=\s+full)|a(?=\s+stop))"
_STOPS = re.compile(
    r"\b(?:(minus|plus)\s+)?"
    rf"(?:{_COUNT}(?:\s+full)?(?:\s+and\s+(a|one|two)[\s-]+thirds?)?|(a|one|two)[\s-]+thirds?)"
    r"(?:\s+of)?\s+(?:an?\s+)?stops?\b"
    r"(?:\s+of\s+(?:flash\s+)?(?:compensation|exposure))?"
    r"(\s+(?:more|less|brighter|darker|over|under|up|down))?",
    re.IGNORECASE,
)
_DOWN_BEFORE = re.compile(r"\b(?:down|lower|reduce|cut|darker|less)\b(?:\s+\w+){0,3}\s+by\s*$")
_HALF_BEFORE = re.compile(r"\bhalf\s*$")
_CLAUSE_START = re.compile(r"(?:^|[,.;:!?])\s*$")
"""Where a value opens the sentence or a clause a leading "-" reads as a dash, not a sign."""
_UP_BEFORE = re.compile(r"\b(?:up|raise|increase|brighter|more)\b(?:\s+\w+){0,3}\s+by\s*$")


def _value_texts(view: Model) -> set[str]:
    return {str(v) for info in view.infos.values() if info.role == "setting" for v in info.values}


def said_power_parts(view: Model, instruction: str) -> str:
    """ "one-sixteenth power plus a third of a stop" as 1/16+0.3 where a setting has it."""
    values = _value_texts(view)
    if not any(re.fullmatch(r"1/\d+", v) for v in values):
        return instruction

    def part(match: re.Match[str]) -> str:
        key = re.sub(r"[\s-]+", "-", match[1].casefold())
        base = f"1/{_PARTS[key]}"
        thirds = {"a": "+0.3", "one": "+0.3", "two": "+0.7"}.get((match[2] or "").casefold(), "")
        return f"{base + thirds} power" if base + thirds in values else match[0]

    return _POWER_PART.sub(part, instruction)


def said_stops(view: Model, instruction: str) -> str:
    """ "minus one and a third stops", "down by two-thirds of a stop", "a full stop more" as
    the signed decimal a compensation setting writes (-1.3, -0.7, +1.0)."""
    values = _value_texts(view)
    signed = {v for v in values if re.fullmatch(r"[+-]\d\.\d", v)}
    if not any(v.endswith((".3", ".7")) for v in signed):
        return instruction

    def stops(match: re.Match[str]) -> str:
        whole = match[2] or ""
        count = (
            0
            if not whole
            else 1
            if whole.casefold() == "a"
            else NUMBER_WORDS.get(whole.casefold(), int(whole) if whole.isdigit() else 0)
        )
        third = (match[3] or match[4] or "").casefold()
        amount = Fraction(count) + Fraction({"a": 1, "one": 1, "two": 2}.get(third, 0), 3)
        if amount == 0:
            return match[0]
        before = instruction[: match.start()].casefold()
        if _HALF_BEFORE.search(before):
            return match[0]  # "half a stop darker": no third of a stop, no full one
        way = (match[5] or "").strip().casefold()
        if (match[1] or "").casefold() == "minus" or way in ("less", "darker", "under", "down"):
            sign = "-"
        elif (match[1] or "").casefold() == "plus" or way in ("more", "brighter", "over", "up"):
            sign = "+"
        elif _DOWN_BEFORE.search(before):
            sign = "-"
        elif _UP_BEFORE.search(before):
            sign = "+"
        else:
            return match[0]
        said = f"{sign}{float(amount):.1f}"
        if said not in signed:
            return match[0]
        if sign == "-" and _CLAUSE_START.search(before):
            return f"minus {said[1:]}"  # "One stop down." as "-1.0" would lose its sign
        return said

    return _STOPS.sub(stops, instruction)
