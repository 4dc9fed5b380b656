"""Thousands on a display that counts in thousands: "fifteen thousand rpm" is the speed 15.

A drill, a centrifuge or a router shows its speed in two digits and prints "×1000 rpm" beside
them; the manual says so ("the speed in thousands of rpm", "12 means 12,000 rpm"). People say
the real figure ("run it at fifteen thousand", "at 12,000 rpm"), which no setting takes. Where
the manual says its display counts in thousands, no number setting takes the figure and one
takes its thousands, the figure is written as its thousands, in the unit the manual names
with them ("15 rpm"), so that a bare "at twelve thousand" still finds the setting of its kind.
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.model.values import NUMBER_WORDS, parse_quantity, words_to_number
from apbot.read.goal_view import Model

_ONES = [w for w, n in NUMBER_WORDS.items() if 1 <= n <= 19 and w not in ("a", "an", "single")]
_TENS = [w for w, n in NUMBER_WORDS.items() if n in range(20, 100, 10)]
_DIGITS = [w for w in _ONES if NUMBER_WORDS[w] <= 9]
_WORD = rf"(?:(?:{'|'.join(_TENS)})(?:[- ](?:{'|'.join(_DIGITS)}))?|{'|'.join(_ONES)})"
_SAID = re.compile(
    rf"\b(?:(?P<word>{_WORD})[ -]thousand|(?P<digits>\d{{1,3}})(?:,000|\s*thousand|k\b)"
    r"(?![\d]|[,.]\d))(?P<unit>\s*(?:rpm|r\.p\.m\.?|revolutions per minute))?",
    re.IGNORECASE,
)
_IN_THOUSANDS = re.compile(
    r"(?:(?<!\w)(?<!\d\s)[×x]\s*1[,.]?000\b"  # "×1000", not "max 1000 W" nor "600 x 1000"
    r"|\bin thousands\b(?: of)?|\bthousands of\b(?=\s*rpm))\s*"
    r"(?P<unit>rpm|[a-zµ/]+)?",
    re.IGNORECASE,
)


def _number(match: re.Match[str]) -> int:
    return int(match["digits"] or words_to_number(match["word"]) or 0)


def _another_unit(word: str) -> bool:
    quantity = parse_quantity(f"1 {word.strip('.,;:!?')}")
    return quantity is not None and quantity[1] not in (None, "speed")


def _counted(word: str) -> bool:
    """A unit ("rpm", "W") or a count of turns that a display may show in thousands; "in
    thousands of kitchens" names none."""
    return not word or word in _TURNS or parse_quantity(f"1 {word}") is not None


_TURNS = frozenset({"revolutions", "rotations", "turns", "strokes", "cycles"})


def _thousands_unit(view: Model) -> str | None:
    """The unit the manual says its display counts in thousands of ("" when it names none);
    None when it says no such thing."""
    found: str | None = None
    for line in view.manual_lines:
        for hit in _IN_THOUSANDS.finditer(line):
            unit = (hit["unit"] or "").casefold()
            if unit in ("rpm", "r.p.m"):
                return "rpm"
            if "thousands" in hit[0].casefold() and not _counted(unit):
                continue  # "used in thousands of kitchens": a boast, no count shown in thousands
            found = found or ""
    return found


def said_thousands(view: Model, instruction: str) -> str:
    """ "at twelve thousand" as "at 12 rpm" where the manual's display counts in thousands."""
    if not _SAID.search(instruction):
        return instruction
    unit = _thousands_unit(view)
    if unit is None:
        return instruction
    figures: set[float] = set()
    for info in view.infos.values():
        if isinstance(info.var, NumericVariable):
            figures.update(float(v) for v in all_values(info.var))

    def figure(match: re.Match[str]) -> str:
        value = _number(match)
        if float(value * 1000) in figures or float(value) not in figures:
            return match[0]
        after = instruction[match.end() :].split(maxsplit=1)
        if not match["unit"] and after and _another_unit(after[0]):
            return match[0]  # "two thousand watts": a quantity of its own unit, no count
        said = match["unit"] or (f" {unit}" if unit else "")
        return f"{value}{said}"

    return _SAID.sub(figure, instruction)
