"""An amount said as small or large before a word of a value's name: "a touch of topspin", "a
little backspin", "lots of steam" — where the manual names the values "light topspin" / "heavy
topspin". People rarely repeat a legend's adjective; they say how much. The phrase is written
with the adjective the model's value names use, only where exactly such a value name exists."""

from __future__ import annotations

import re

from apbot.read.goal_view import Model
from apbot.read.goal_vocab import stem

_SMALL = r"(?:a\s+(?:little|touch|bit|hint|dash)(?:\s+of)?|slight|some\s+slight|just\s+a\s+little)"
_LARGE = r"(?:(?:a\s+)?lots?\s+of|plenty\s+of|a\s+great\s+deal\s+of|maximum|loads\s+of)"
_SAID = re.compile(rf"\b({_SMALL}|{_LARGE})\s+([a-z]+)\b", re.IGNORECASE)
_SMALL_WORDS = ("light", "slight", "low", "mild", "gentle", "little", "soft")
_LARGE_WORDS = ("heavy", "strong", "high", "intense", "max", "maximum")


def said_amounts(view: Model, instruction: str) -> str:
    """ "a touch of topspin" as "light topspin" where a value is named LIGHT TOPSPIN."""
    pairs = {stems for _var, _value, stems, _weight in view.phrases if len(stems) == 2}
    if not pairs:
        return instruction

    def amount(match: re.Match[str]) -> str:
        small = re.fullmatch(_SMALL, match[1], re.IGNORECASE) is not None
        noun = stem(match[2].casefold())
        named = [w for w in (_SMALL_WORDS if small else _LARGE_WORDS) if (stem(w), noun) in pairs]
        if len(named) != 1:
            return match[0]
        if match[1].casefold() == "maximum" and not _an_end(view, (stem(named[0]), noun)):
            return match[0]  # "maximum heat" past HIGH HEAT to BOOST: the end, not HIGH
        return f"{named[0]} {match[2]}"

    return _SAID.sub(amount, instruction)


def _an_end(view: Model, stems: tuple[str, ...]) -> bool:
    """The value named by ``stems`` is the first or last of its setting's values."""
    for var, value, said, _weight in view.phrases:
        values = list(view.infos[var].values) if var in view.infos else []
        if said == stems and values and value in (values[0], values[-1]):
            return True
    return False
