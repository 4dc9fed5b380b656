"""A quantity said in full where the panel shows it in thousands: "fifteen thousand rpm" is 15.

A speed of 3,000–35,000 rpm on a two-digit display is printed 3 … 35, and the manual says so
("the display shows the speed in thousands: 12 means 12,000 rpm", "×1000 rpm" beside the
digits). The read setting then runs 3–35 while the user says the real figure. The figure is
written as its thousands only where that is the one reading: the manual speaks of thousands,
some number setting takes the thousandth, and none takes the figure itself.
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.read.goal_view import Model
from apbot.read.number_tokens import read_number, tokenize

# the manual saying its figures are thousands: "in thousands", "×1000 rpm", "x 1,000"
_THOUSANDS_SAID = re.compile(r"\bin\s+thousands\b|[×x]\s?1[,.]?000\b", re.IGNORECASE)
_DIGITS = re.compile(r"\b(\d{1,3}),?000\b(?![.,]\d)")
_WORDS = re.compile(r"\b((?:[a-z]+[- ]){0,2}[a-z]+)\s+thousand\b", re.IGNORECASE)


def _figures(view: Model) -> set[float]:
    """Every number some number setting of the model takes."""
    found: set[float] = set()
    for info in view.infos.values():
        if isinstance(info.var, NumericVariable):
            found.update(float(v) for v in all_values(info.var))
    return found


def _spoken(words: str) -> float | None:
    """The number the words before "thousand" say ("twenty-five"), read from their end."""
    tokens = tokenize(words)
    for start in range(len(tokens)):
        number = read_number(tokens, start)
        if number is not None and number.end == len(tokens):
            return number.value
    return None


def said_thousands(view: Model, instruction: str) -> str:
    """ "fifteen thousand" and "15,000" as "15" where the panel shows the setting in thousands."""
    if "thousand" not in instruction.casefold() and not _DIGITS.search(instruction):
        return instruction
    if not any(_THOUSANDS_SAID.search(line) for line in view.manual_lines):
        return instruction
    figures = _figures(view)

    def shown(value: float) -> str | None:
        if value in figures or value / 1000 not in figures:
            return None
        return f"{value / 1000:g}"

    def from_digits(match: re.Match[str]) -> str:
        return shown(float(match[1]) * 1000) or match[0]

    def from_words(match: re.Match[str]) -> str:
        value = _spoken(match[1])
        if value is None:
            return match[0]
        figure = shown(value * 1000)
        if figure is None:
            return match[0]
        lead = match[1]
        tokens = tokenize(lead)
        kept = next(
            (
                " ".join(t.text for t in tokens[:k])
                for k in range(len(tokens))
                if (n := read_number(tokens, k)) is not None and n.end == len(tokens)
            ),
            "",
        )
        return f"{kept} {figure}".strip()

    return _DIGITS.sub(from_digits, _WORDS.sub(from_words, instruction))
