"""Values written as a fraction ("6/8", "3/4": a time signature, a share) said the way people
say them.

- "six-eight", "five-four time", "in 12-8" are 6/8, 5/4, 12/8 — only where a setting lists that
  value, so "a two-four" elsewhere stays two numbers;
- a name the manual gives one such value right after it, in a list set apart by middle dots
  ("3/4 waltz · 4/4 common time"), names it: "waltz time", "in common time".
  A name two values share ("6/8 and 12/8 compound time") names neither.

Both are written as the value before the sentence is read (the figures would otherwise go to a
numbered setting: "six-eight" is no kit 6).
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import DiscreteVariable
from apbot.model.values import words_to_number
from apbot.read.goal_view import Model

_FRACTION = re.compile(r"\d{1,2}/\d{1,2}")
_WORD = (
    r"(?:\d{1,2}|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|sixteen"
    r"|thirty-two)"
)
_SAID = re.compile(rf"\b({_WORD})(?:-|\s+)({_WORD})(?=(\s+time\b)?)", re.IGNORECASE)
_NAMED = re.compile(r"(\d{1,2}/\d{1,2})\s+([a-z][a-z' ]{2,24}?)\s*(?=·|$|\()")
_MAX_NAME_WORDS = 2


def _fractions(view: Model) -> set[str]:
    """The fraction-shaped values of discrete settings ("6/8")."""
    return {
        str(v)
        for info in view.infos.values()
        if isinstance(info.var, DiscreteVariable)
        for v in all_values(info.var)
        if _FRACTION.fullmatch(str(v))
    }


def _names(view: Model, values: set[str]) -> dict[str, str]:
    """name -> value for the names the manual gives one fraction value right after it."""
    found: dict[str, set[str]] = {}
    for line in view.manual_lines:
        if "·" not in line:
            continue  # a list of names set apart by middle dots, not a sentence or a chart
        for segment in line.split("·"):
            if len(_FRACTION.findall(segment)) != 1:
                continue  # "6/8 and 12/8 compound time": a name two values share
            for value, name in _NAMED.findall(segment.strip()):
                words = name.split()
                if value in values and 0 < len(words) <= _MAX_NAME_WORDS:
                    found.setdefault(" ".join(words), set()).add(value)
    return {name: next(iter(vs)) for name, vs in found.items() if len(vs) == 1}


def said_meters(view: Model, instruction: str) -> str:
    """ "five-four time" as "5/4 time"; "waltz time" as "3/4 time" (the manual's name)."""
    values = _fractions(view)
    if len(values) < 2:
        return instruction

    def number(word: str) -> str | None:
        value = words_to_number(word)
        return str(int(value)) if value is not None and value.is_integer() else None

    def written(m: re.Match[str]) -> str:
        top, bottom = number(m[1]), number(m[2])
        joined = m[0][len(m[1]) : len(m[0]) - len(m[2])]
        if top is None or bottom is None or f"{top}/{bottom}" not in values:
            return m[0]
        if "-" not in joined and not m[3]:
            return m[0]  # "six eight" alone may be two numbers; "six eight time" is not
        return f"{top}/{bottom}"

    said = _SAID.sub(written, instruction)
    for name, value in _names(view, values).items():
        said = re.sub(rf"\b{re.escape(name)}\b", value, said, flags=re.IGNORECASE)
    return said
