"""A value shown as a count and a word ("2 TONE", "3 BLADE", "4 ZONE") said as one hyphenated
adjective: "two-tone audio", "a 4-zone setup". The hyphen keeps the figure from reaching the
word, so the figure alone would go to another setting (a sensitivity 2); the compound is written
as the display writes it, only where a setting shows exactly that count and word.
"""

from __future__ import annotations

import re

from apbot.model.schema import DiscreteVariable
from apbot.model.values import words_to_number
from apbot.read.goal_view import Model

_SHOWN = re.compile(r"^\s*(\d{1,3})\s+([A-Za-z]{3,})\s*$")
_SAID = re.compile(r"\b(\d{1,3}|[A-Za-z]+)-([A-Za-z]{3,})\b")


def _shown_counts(view: Model) -> set[tuple[int, str]]:
    """(count, word) of each discrete value shown as a count and one word."""
    found = set()
    for info in view.infos.values():
        var = info.var
        if not isinstance(var, DiscreteVariable):
            continue
        shows = var.show.values() if isinstance(var.show, dict) else ()
        for text in [*map(str, shows), *map(str, var.values or ())]:
            m = _SHOWN.match(text.replace("_", " "))
            if m:
                found.add((int(m[1]), m[2].casefold()))
    return found


def said_hyphen_counts(view: Model, instruction: str) -> str:
    """ "two-tone" as "2 tone" where a setting shows 2 TONE."""
    shown = _shown_counts(view)
    if not shown:
        return instruction

    def spaced(m: re.Match[str]) -> str:
        count = words_to_number(m[1])
        word = m[2].casefold()
        for candidate in (word, word.rstrip("s")):
            if count is not None and count.is_integer() and (int(count), candidate) in shown:
                return f"{int(count)} {m[2]}"
        return m[0]

    return _SAID.sub(spaced, instruction)
