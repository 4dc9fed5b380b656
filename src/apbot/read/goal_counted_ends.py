"""A place counted from an end of a scale: "one below the top speed", "second from the bottom",
"two under the maximum". People step back from an end they know rather than name the value;
the phrase is written as "the second highest" / "the third lowest", which the superlatives read
as that many steps back from the end (:func:`apbot.read.goal_scales.superlatives`)."""

from __future__ import annotations

import re

from apbot.read.goal_view import Model

_COUNTS = {"one": 1, "a": 1, "1": 1, "two": 2, "2": 2}
_ORDINALS = {1: "second", 2: "third"}
_FROM = {"second": "second", "third": "third", "2nd": "second", "3rd": "third"}
_TOP = r"(?:top|highest|maximum|max|fastest|strongest|hottest|loudest|brightest)"
_BOTTOM = r"(?:bottom|lowest|minimum|min|slowest|weakest|coolest|quietest|dimmest)"
_STEP = r"(?:\s+(?:step|notch|level|setting|click)s?)?"
_BELOW_TOP = re.compile(
    rf"\b(one|a|two|1|2){_STEP}\s+(?:below|under|short\s+of|down\s+from|less\s+than)"
    rf"\s+the\s+({_TOP})\b",
    re.IGNORECASE,
)
_ABOVE_BOTTOM = re.compile(
    rf"\b(one|a|two|1|2){_STEP}\s+(?:above|over|up\s+from|more\s+than)\s+the\s+({_BOTTOM})\b",
    re.IGNORECASE,
)
_FROM_END = re.compile(
    r"\b(second|third|2nd|3rd)\s+(?:([a-z]+)\s+)?from\s+the\s+(top|bottom)\b", re.IGNORECASE
)


def counted_ends(view: Model, instruction: str) -> str:
    """ "one below the top speed" as "the second highest speed"."""

    def below(match: re.Match[str]) -> str:
        return f"the {_ORDINALS[_COUNTS[match[1].casefold()]]} highest"

    def above(match: re.Match[str]) -> str:
        return f"the {_ORDINALS[_COUNTS[match[1].casefold()]]} lowest"

    def from_end(match: re.Match[str]) -> str:
        end = "highest" if match[3].casefold() == "top" else "lowest"
        noun = f" {match[2]}" if match[2] else ""
        return f"{_FROM[match[1].casefold()]} {end}{noun}"

    said = _BELOW_TOP.sub(below, instruction)
    said = _ABOVE_BOTTOM.sub(above, said)
    return _FROM_END.sub(from_end, said)
