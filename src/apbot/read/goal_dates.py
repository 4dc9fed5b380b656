"""A date said the way people say it ("the fourteenth of February", "3rd of July", "March 1st")
on a model that keeps the date as a DAY and a MONTH setting: written "month 2, day 14", which the
rest of the parser reads as each setting's number. Without it "the thirty-first" is read as 30
and the month's name as nothing. Only where both settings exist, so a month said elsewhere ("a
two-month holiday", "in May") is left alone."""

from __future__ import annotations

import re

from apbot.read.goal_view import Model
from apbot.read.goal_vocab import concept

MONTHS = (
    "january", "february", "march", "april", "may", "june",
    "july", "august", "september", "october", "november", "december",
)  # fmt: skip
_UNITS = (
    "first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth",
)  # fmt: skip
_TEENS = (
    "tenth", "eleventh", "twelfth", "thirteenth", "fourteenth", "fifteenth", "sixteenth",
    "seventeenth", "eighteenth", "nineteenth",
)  # fmt: skip
DAY_ORDINALS: dict[str, int] = {w: n for n, w in enumerate(_UNITS, 1)}
DAY_ORDINALS |= {w: n for n, w in enumerate(_TEENS, 10)}
DAY_ORDINALS |= {"twentieth": 20, "thirtieth": 30}
DAY_ORDINALS |= {f"twenty-{w}": 20 + n for n, w in enumerate(_UNITS, 1)}
DAY_ORDINALS |= {"thirty-first": 31}

_ORDINAL = (
    r"(?:\d{1,2}(?:st|nd|rd|th)|" + "|".join(sorted(DAY_ORDINALS, key=len, reverse=True)) + ")"
)
_MONTH = "(" + "|".join(MONTHS) + ")"
_DAY_FIRST = re.compile(rf"\b(?:the\s+)?({_ORDINAL})\s+(?:of\s+)?{_MONTH}\b", re.IGNORECASE)
_MONTH_FIRST = re.compile(
    rf"\b{_MONTH}\s+(?:the\s+)?({_ORDINAL}|\d{{1,2}})\b(?!\s*(?::|am|pm|a\.m|p\.m|h\b|hours?))",
    re.IGNORECASE,
)


def _day_number(said: str) -> int | None:
    said = said.casefold().replace(" ", "-")
    if said in DAY_ORDINALS:
        return DAY_ORDINALS[said]
    digits = re.match(r"\d+", said)
    day = int(digits[0]) if digits else 0
    return day if 1 <= day <= 31 else None


def said_dates(view: Model, instruction: str) -> str:
    """ "the fourteenth of February" as "month 2, day 14" where DAY and MONTH are settings."""
    words = {key for info in view.infos.values() if info.role == "setting" for key in info.vocab}
    if concept("day") not in words or concept("month") not in words:
        return instruction

    def written(day_said: str, month_said: str, whole: str) -> str:
        day = _day_number(day_said)
        if day is None:
            return whole
        return f"month {MONTHS.index(month_said.casefold()) + 1}, day {day}"

    instruction = _DAY_FIRST.sub(lambda m: written(m[1], m[2], m[0]), instruction)
    return _MONTH_FIRST.sub(lambda m: written(m[2], m[1], m[0]), instruction)
