"""Quantities said in another unit than the setting shows: a road speed and a rate.

- "ninety-seven kilometres an hour" on a dial in mph (and miles on a km/h dial) is converted
  and taken when it lands on one of the dial's values (a manual's conversion table rounds the
  same way: 97 km/h is its 60 mph); "fifty miles an hour" is "50 mph".
- "twenty balls a minute" on a setting of the seconds between two of them (a feed interval,
  a metronome's beat) is one every three seconds — only where the manual counts the same
  thing per minute, and the seconds land on one of the setting's values.

Both are written as the setting's own unit before the sentence is read.
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.model.values import words_to_number
from apbot.read.goal_view import Model

_NUMBER = r"(\d+(?:\.\d+)?|(?:[a-z]+[\s-]+){0,3}?[a-z]+)"
_MILES = re.compile(rf"\b{_NUMBER}\s+(miles|kilomet(?:re|er)s?|km)\s+(?:an|a|per)\s+hour\b", re.I)
_KMH = re.compile(r"\b(\d+(?:\.\d+)?)\s*(?:km/h|kph|kmh|km/hr)\b", re.IGNORECASE)
_PER_MINUTE = re.compile(
    rf"\b{_NUMBER}\s+([a-z]+s)\s+(?:a|per|each|every)\s+minute\b(?!\s*(?:for|of)\b)", re.I
)
_KM_PER_MILE = 1.609344
_CLOSE = 0.03
"""How far a converted speed may land from a dial's value (a table rounds to whole units)."""


def _number(said: str) -> tuple[str, float | None]:
    """The words before the number at the end of ``said`` and the number ("set ninety-seven",
    "97"): the longest tail that reads as one."""
    words = said.split()
    for start in range(len(words)):
        value = words_to_number(" ".join(words[start:]))
        if value is not None:
            return " ".join(words[:start]) + (" " if start else ""), value
    return said, None


def _speeds(view: Model, unit: str) -> list[float]:
    """The values of the one numeric setting shown in ``unit`` ("mph"), or []."""
    found = [
        [float(v) for v in all_values(info.var)]
        for info in view.infos.values()
        if isinstance(info.var, NumericVariable)
        and info.role == "setting"
        and (info.var.unit or "").strip().casefold().replace("kph", "km/h") == unit
    ]
    return found[0] if len(found) == 1 else []


def _landed(value: float, values: list[float]) -> float | None:
    nearest = min(values, key=lambda v: abs(v - value), default=None)
    if nearest is None or abs(nearest - value) > _CLOSE * max(abs(nearest), 1.0):
        return None
    return nearest


def _text(value: float) -> str:
    return str(int(value)) if value.is_integer() else str(value)


def said_road_speeds(view: Model, instruction: str) -> str:
    """ "97 kilometres an hour" as "60 mph" on a mph dial; "50 miles an hour" as "50 mph"."""
    mph, kmh = _speeds(view, "mph"), _speeds(view, "km/h")
    if not mph and not kmh:
        return instruction

    def speed(said: str, miles: bool, whole: str) -> str:
        head, value = _number(said)
        if value is None:
            return whole
        if miles and mph:
            return f"{head}{_text(value)} mph"
        if not miles and kmh:
            return f"{head}{_text(value)} km/h"
        target = mph if mph else kmh
        converted = value / _KM_PER_MILE if mph else value * _KM_PER_MILE
        landed = _landed(converted, target)
        unit = "mph" if mph else "km/h"
        return whole if landed is None else f"{head}{_text(landed)} {unit}"

    said = _MILES.sub(lambda m: speed(m[1], m[2].casefold() == "miles", m[0]), instruction)
    return _KMH.sub(lambda m: speed(m[1], False, m[0]), said)


def _counted_between(manual: str, things: str) -> bool:
    """The manual counts ``things`` per minute and says the setting waits between them
    ("balls per minute", "the time between two balls"): "litres a minute" is a flow, no
    count of things a seconds-between setting spaces out."""
    one = re.escape(things.casefold().removesuffix("s"))
    per = re.search(rf"\b{one}s?\s+(?:per|a)\s+minute\b", manual)
    between = re.search(rf"\bbetween\s+(?:two\s+|each\s+|successive\s+)?{one}s?\b", manual)
    return per is not None and between is not None


def said_rates(view: Model, instruction: str) -> str:
    """ "twenty balls a minute" as "one every 3 seconds" on a seconds-between setting."""
    if "per minute" not in " ".join(view.manual_lines):
        return instruction
    manual = " ".join(" ".join(line.split()) for line in view.manual_lines).casefold()
    gaps = [
        [float(v) for v in all_values(info.var)]
        for info in view.infos.values()
        if isinstance(info.var, NumericVariable)
        and info.role == "setting"
        and (info.var.unit or "").strip().casefold() in ("s", "sec", "seconds")
    ]
    if len(gaps) != 1:
        return instruction

    def rate(match: re.Match[str]) -> str:
        if not _counted_between(manual, match[2]):
            return match[0]
        head, count = _number(match[1])
        if not count or count <= 1:
            return match[0]
        landed = _landed(60 / count, gaps[0])
        if landed is None or abs(landed - 60 / count) > 0.05:
            return match[0]
        return f"{head}one every {_text(landed)} seconds"

    return _PER_MINUTE.sub(rate, instruction)
