"""Hundreds said the short way: "one fifty" is 150, "one eighty-five" 185.

People read a three-figure setting (an oil or oven temperature, a speed, a weight) as two
numbers — "oil at one fifty", "bake at three seventy-five" — dropping "hundred". The number
reader takes "one" and "fifty" for two numbers, so the phrase is written as its figure first,
only where it can mean nothing else: the model has no time of day (where "seven thirty" is
half past seven), no time word follows it, and some number setting takes the figure.
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.read.goal_view import Model

_UNITS = ("one", "two", "three", "four", "five", "six", "seven", "eight", "nine")
_TENS = ("twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")
_SHORT_HUNDREDS = re.compile(
    rf"\b({'|'.join(_UNITS)})[ -]({'|'.join(_TENS)})(?:[- ]({'|'.join(_UNITS)}))?\b"
    r"(?!\s*(?:a\.?m\b|p\.?m\b|o'clock|in\s+the\s+(?:morning|afternoon|evening)|at\s+night"
    r"|tonight|minutes?|mins?|hours?|hrs?|seconds?|secs?))",
    re.IGNORECASE,
)


def _figures(view: Model) -> set[float] | None:
    """The numbers some number setting takes; None on a model that keeps a time of day."""
    if any(info.timing in ("clock", "at", "finish") for info in view.infos.values()):
        return None
    found: set[float] = set()
    for info in view.infos.values():
        if isinstance(info.var, NumericVariable):
            found.update(float(v) for v in all_values(info.var) if float(v) >= 100)
    return found


def said_hundreds(view: Model, instruction: str) -> str:
    """ "one fifty" as "150" where a number setting of the model takes 150."""
    if not _SHORT_HUNDREDS.search(instruction):
        return instruction
    figures = _figures(view)
    if not figures:
        return instruction

    def figure(match: re.Match[str]) -> str:
        value = 100 * (_UNITS.index(match[1].casefold()) + 1)
        value += 10 * (_TENS.index(match[2].casefold()) + 2)
        value += _UNITS.index(match[3].casefold()) + 1 if match[3] else 0
        return str(value) if float(value) in figures else match[0]

    return _SHORT_HUNDREDS.sub(figure, instruction)
