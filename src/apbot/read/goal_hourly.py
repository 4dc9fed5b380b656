"""How often and how long, said in the words people use for them rather than a number: "an
hourly reminder" is every 1 hour, "every hour and a half" every 1.5 hours, "every hour" every
1 hour, "an hour's sleep timer" a timer of an hour. The rest of the parser reads a number beside
its unit ("every 1 hour", "an hour"), so the phrase is written that way first. A phrase one of
the model's values is literally named by ("HOURLY", "EVERY HOUR") is left to that value's name.
"""

from __future__ import annotations

import re

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_view import Model

_REWRITES = (
    (re.compile(r"\bhalf[- ]hourly\b", re.IGNORECASE), "every 30 minutes"),
    (re.compile(r"\b(?:an?\s+)?hourly\b", re.IGNORECASE), "every 1 hour"),
    (re.compile(r"\bevery\s+hour\s+and\s+a\s+half\b", re.IGNORECASE), "every 1.5 hours"),
    (re.compile(r"\bevery\s+hour\b(?!\s+and\b)", re.IGNORECASE), "every 1 hour"),
    # a possessive of a length: "an hour's timer", "ten minutes' rest"
    (re.compile(r"\b(second|minute|hour|day|week)['\u2019]s\b", re.IGNORECASE), r"\1"),
    (re.compile(r"\b(seconds|minutes|hours|days|weeks)['\u2019](?=\s|$)", re.IGNORECASE), r"\1"),
)


def hourly_periods(view: Model, instruction: str) -> str:
    """Rewrite "hourly", "every hour (and a half)", "an hour's" with a number and a unit."""
    named = " ".join(
        str(value).casefold()
        for info in view.infos.values()
        if isinstance(info.var, DiscreteVariable)
        for value in info.values
    )
    for pattern, replacement in _REWRITES:

        def number(match: re.Match[str], written: str = replacement) -> str:
            return match[0] if match[0].casefold() in named else match.expand(written)

        instruction = pattern.sub(number, instruction)
    return instruction
