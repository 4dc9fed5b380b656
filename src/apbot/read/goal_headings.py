"""Compass headings as people say them: "steer zero four five", "course one-one-zero", "due north".

A heading is read out one digit at a time ("two five five" is 255, never 2, 5 and 5), and a
cardinal point stands for its bearing (north 0, east 90, south 180, west 270). Both are
rewritten to the number before the instruction is read — only on a model with a setting that
holds a whole turn in degrees (a ° setting from 0 to at least 350), so three small numbers or a
"north-facing room" elsewhere are left alone. The run must be three digit *words* (or figures
joined by hyphens), set apart by spaces or hyphens, and spell a heading the setting can take.
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.model.values import DIGIT_WORDS
from apbot.read.goal_view import Model

_DIGIT_WORDS = {w: str(n) for w, n in DIGIT_WORDS.items()} | {"oh": "0"}
_WORD = "(?:" + "|".join(_DIGIT_WORDS) + ")"
# three digit words ("zero four five"), or three figures joined by hyphens ("1-1-0")
_RUN = re.compile(
    rf"\b(?:{_WORD}(?:[ -]{_WORD}){{2}}|\d-\d-\d)\b(?![ -](?:{_WORD}|\d)\b)"
    r"(?:\s*(?:degrees?\b|°))?",
    re.IGNORECASE,
)
_AFTER_DIGIT = re.compile(rf"\b(?:{_WORD}|\d)[ -]$", re.IGNORECASE)
_POINTS = {
    "north": 0,
    "northeast": 45,
    "east": 90,
    "southeast": 135,
    "south": 180,
    "southwest": 225,
    "west": 270,
    "northwest": 315,
}
_POINT = re.compile(
    r"(?:\b(due\s+)?(north|south)(?:[ -]?(east|west))?\b|\b(due\s+)?(east|west)\b)"
    r"(?![ -](?:facing|side|wall|window|winds?)\b)",
    re.IGNORECASE,
)


def _headings(view: Model) -> set[int]:
    """The bearings a whole-turn degree setting takes (empty when the model has none)."""
    for info in view.infos.values():
        var = info.var
        if info.role != "setting" or not isinstance(var, NumericVariable):
            continue
        if (var.unit or "").strip().casefold() not in ("°", "deg", "degree", "degrees"):
            continue
        try:
            values = {float(v) for v in all_values(var)}
        except (TypeError, ValueError):
            continue
        if min(values) <= 0 and max(values) >= 350:
            return {int(v) for v in values if float(v).is_integer()}
    return set()


def said_headings(view: Model, instruction: str) -> str:
    """ "steer zero four five" as "steer 45 degrees", "due south" as "180 degrees"."""
    headings = _headings(view)
    if not headings:
        return instruction

    def spelled(match: re.Match[str]) -> str:
        if _AFTER_DIGIT.search(match.string[: match.start()]):
            return match[0]  # the end of a longer run ("one two three four")
        said = re.sub(r"\s*(?:degrees?|°)$", "", match[0], flags=re.IGNORECASE)
        digits = "".join(_DIGIT_WORDS.get(p.casefold(), p) for p in re.split(r"[ -]", said))
        number = int(digits)
        return f"{number} degrees" if number in headings else match[0]

    def point(match: re.Match[str]) -> str:
        if match[5]:
            name = match[5].casefold()
        else:
            name = match[2].casefold() + (match[3] or "").casefold()
        bearing = _POINTS[name]
        return f"{bearing} degrees" if bearing in headings else match[0]

    return _POINT.sub(point, _RUN.sub(spelled, instruction))
