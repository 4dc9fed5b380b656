"""A setting said as a part of its top: "a quarter of full speed", "three-quarters speed",
"two thirds of maximum power".

On a numbered setting that counts from nothing (0 or 1 up to its top, as a speed of 0-28 steps
does) the part is taken of the top and rounded to the nearest of its values: a quarter of 28 is
7, three quarters 21. Half is left to :mod:`apbot.read.goal_halfway` (the middle of the working
levels). The phrase is rewritten to the setting's name and number before the sentence is read.
Only where the setting's own word follows the part (with "of", "full", "max", "top" between).
"""

from __future__ import annotations

import re

from apbot.model.domain import build_domain
from apbot.model.schema import NumericVariable
from apbot.read.goal_view import Model
from apbot.read.goal_vocab import stem

_PARTS = {
    "a quarter": 0.25,
    "one quarter": 0.25,
    "quarter": 0.25,
    "three quarters": 0.75,
    "three-quarters": 0.75,
    "three-quarter": 0.75,
    "three quarter": 0.75,
    "a third": 1 / 3,
    "one third": 1 / 3,
    "one-third": 1 / 3,
    "two thirds": 2 / 3,
    "two-thirds": 2 / 3,
}
_SAID = re.compile(
    r"\b(?P<part>"
    + "|".join(sorted((re.escape(p) for p in _PARTS), key=len, reverse=True))
    + r")\s+(?:of\s+)?(?:(?:the|its)\s+)?(?:(?:full|max|maximum|top)\s+)?(?P<word>[a-z]+)\b",
    re.IGNORECASE,
)


def said_parts_of_top(view: Model, instruction: str) -> str:
    """ "a quarter of full speed" as "speed 7" on a speed of 0-28."""

    def part(m: re.Match[str]) -> str:
        key = stem(m["word"].casefold())
        named = [
            n
            for n, info in view.infos.items()
            if info.role == "setting"
            and isinstance(info.var, NumericVariable)
            and not info.var.depends_on
            and info.vocab.get(key, 0.0) >= 1.0
        ]
        if len(named) != 1:
            return m[0]
        domain = build_domain(view.infos[named[0]].var)
        numbers = domain.magnitudes or ()
        if len(numbers) < 4 or numbers[0] not in (0.0, 1.0):
            return m[0]
        target = _PARTS[re.sub(r"\s+", " ", m["part"].casefold())] * numbers[-1]
        at = min(range(len(numbers)), key=lambda i: abs(numbers[i] - target))
        return f"{named[0].replace('_', ' ')} {domain.values[at]}"

    return _SAID.sub(part, instruction)
