"""Electrical units: a setting kept in volts or amps is named by them ("five volts at two
amps"), and a current said in milliamps is a fraction of an amp ("a 300 milliamp limit").

The quantity reader knows no electrical unit, so a bare "twelve volts" was a number that named
no setting, and "fifty milliamps" read 50 A (or nothing). A numeric setting whose unit is V, A
or Hz takes the unit's spoken names as its own words; milliamps are written as amps where some
setting counts in amps. Both follow from the model's units alone.
"""

from __future__ import annotations

import re

from apbot.model.schema import NumericVariable
from apbot.model.values import words_to_number
from apbot.read.goal_values import unit_text
from apbot.read.goal_view import Model

_NUMBER_WORD = (
    r"(?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen"
    r"|fifteen|sixteen|seventeen|eighteen|nineteen|twenty|thirty|forty|fifty|sixty|seventy"
    r"|eighty|ninety|hundred|thousand)"
)
_MILLIAMPS = re.compile(
    rf"\b(?P<number>\d+(?:\.\d+)?|(?:an?\s+)?{_NUMBER_WORD}(?:(?:\s+and\s+|[\s-]+){_NUMBER_WORD})*)"
    r"\s*(?:-\s*)?(?:milliamps?|milliamperes?|mA)\b",
    re.IGNORECASE,
)


def said_milliamps(view: Model, instruction: str) -> str:
    """ "300 milliamps" as "0.3 amps" where a setting counts in amps."""
    if not _MILLIAMPS.search(instruction):
        return instruction
    if not any(
        isinstance(info.var, NumericVariable) and unit_text(info.var).casefold() == "a"
        for info in view.infos.values()
    ):
        return instruction

    def amps(match: re.Match[str]) -> str:
        said = re.sub(r"^an?\s+(?=hundred|thousand)", "one ", match["number"], flags=re.I)
        number = words_to_number(re.sub(r"^an?\s+", "", said, flags=re.I))
        return match[0] if number is None else f"{number / 1000:g} amps"

    return _MILLIAMPS.sub(amps, instruction)
