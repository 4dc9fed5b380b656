"""What the names and values of a model look like to the goal parser: the words of a name, the
words and numbers of a value's name, quantities and magnitudes, an on/off pair."""

from __future__ import annotations

import re
import unicodedata
from functools import lru_cache
from typing import Any

from apbot.model.schema import NumericVariable
from apbot.model.values import parse_quantity as _parse_quantity
from apbot.model.values import unit_of
from apbot.read.goal_vocab import concept, split_camel
from apbot.read.number_tokens import tokenize

ON_WORDS = ("on", "yes", "enabled", "true")


OFF_WORDS = ("off", "no", "disabled", "false")


@lru_cache(maxsize=65536)
def parse_quantity(text: str) -> tuple[float, str | None, float] | None:
    """:func:`apbot.model.values.parse_quantity`, remembered: value lists are read per mention;
    a value counting days or weeks ("2 d", an interval "every 2 days") is a time too, as
    :func:`unit_kind` reads a setting's unit."""
    found = _parse_quantity(text)
    if found is None:
        long = _LONG_QUANTITY.fullmatch(text.strip())
        seconds = _LONG_UNITS.get(long[2].casefold()) if long else None
        if long and seconds:
            return float(long[1]) * seconds, "time", 1.0
    return found


def name_words(text: str) -> list[str]:
    """The words of a variable's name or label ("keepWarm_time": keep, warm, time)."""
    return [t.text for t in tokenize(split_camel(text.replace("_", " "))) if t.text.isalpha()]


def phrase_words(text: str) -> list[str]:
    """Words and numbers of a value's name ("quick 20", "eco 40-60", "A-6")."""
    words = tokenize(split_camel(text.replace("_", " ")))
    return [t.text for t in words if t.text.replace(".", "").isalnum()]


def on_off_pair(values: list[Any]) -> tuple[str, str] | None:
    """(on, off) of a two-valued switch ("on"/"off", "yes"/"no", "locked"/"unlocked")."""
    lowered = [str(v).casefold() for v in values]
    if len(values) != 2:
        return None
    if sorted(lowered) == ["locked", "unlocked"]:  # a lock: on is locked
        return str(values[lowered.index("locked")]), str(values[lowered.index("unlocked")])
    on = next((values[i] for i, v in enumerate(lowered) if v in ON_WORDS), None)
    off = next((values[i] for i, v in enumerate(lowered) if v in OFF_WORDS), None)
    if on is None or off is None:
        return None
    return str(on), str(off)


def unit_text(var: NumericVariable) -> str:
    """The variable's unit in plain letters: a one-character "℃" is "°C" (NFKC)."""
    return unicodedata.normalize("NFKC", var.unit).strip()


_LONG_UNITS = {
    "d": 86400,
    "day": 86400,
    "days": 86400,
    "wk": 604800,
    "wks": 604800,
    "week": 604800,
    "weeks": 604800,
}


_LONG_QUANTITY = re.compile(r"(\d+(?:\.\d+)?)\s?([A-Za-z]+)\.?")


def unit_kind(unit: str) -> tuple[str, float] | None:
    """Dimension and factor of a setting's unit: :func:`unit_of`, and days and weeks too, the
    units of an absence or a fermentation (DAYS 1-45), which are times like hours.

    >>> unit_kind("d"), unit_kind("min")
    (('time', 86400), ('time', 60))
    """
    found = unit_of(unit)
    if found is not None:
        return found
    seconds = _LONG_UNITS.get(unit.strip().casefold().rstrip("."))
    return ("time", seconds) if seconds else None


def in_days(var: Any) -> bool:
    """A count of days (DAYS 1-45 of an absence): a duration, though "day" is a clock's word."""
    unit = unit_kind(unit_text(var)) if isinstance(var, NumericVariable) else None
    return unit is not None and unit[0] == "time" and unit[1] >= 86400


def numeric_values(values: list[Any]) -> bool:
    numeric = [v for v in values if parse_quantity(str(v)) is not None]
    return len(numeric) >= max(1, len(values) - 2)


def quantity_dimensions(values: list[Any]) -> set[str]:
    """Dimensions that at least two values are quantities of ("100 W", "450 W")."""
    counts: dict[str, int] = {}
    for value in values:
        q = parse_quantity(str(value))
        if q is not None and q[1] is not None:
            counts[q[1]] = counts.get(q[1], 0) + 1
    return {d for d, c in counts.items() if c >= 2}


def bare_number(value: Any) -> float | None:
    """A value that is a plain number ("-16", "+4", "3.5"), without a unit; else None."""
    q = parse_quantity(str(value))
    return q[0] if q is not None and q[1] is None else None


def magnitude(value: Any) -> float | None:
    if isinstance(value, int | float):
        return float(value)
    text = str(value)
    if text.count(":") == 2:
        h, m, sec = (int(x) for x in text.split(":"))
        return float(h * 3600 + m * 60 + sec)
    return None


_GENERIC = frozenset(
    concept(w) for w in ("program", "time", "temperature", "level", "power", "size", "water")
)


_KIND_NOUNS = frozenset(concept(w) for w in ("program", "time", "level", "power", "size"))
"""Of the general words, those that say what kind of setting is meant (any setting may be
"the time", "the level"), not what it acts on (heat, water)."""


def generic(key: str) -> bool:
    return key in _GENERIC


def kind_noun(key: str) -> bool:
    return key in _KIND_NOUNS


def zone_case(var: Any) -> str | None:
    """The setting a per-zone level depends on (BODY / FEET each keep a level 1-9): the
    ``depends_on`` of a numeric setting whose two or more cases all have one range."""
    cases = getattr(var, "cases", None)
    depends = getattr(var, "depends_on", None)
    if not isinstance(var, NumericVariable) or not depends or not cases or len(cases) < 2:
        return None
    return depends if len({repr(case.ranges) for case in cases.values()}) == 1 else None


# a count shown with its unit's letter glued on, either side: "W 3d", "d2", "12H"
_SHOWN_COUNT = re.compile(r"(?<![A-Za-z0-9])(?:(\d+)([dh])|([dh])(\d+))(?![A-Za-z0-9])", re.I)
_LETTER_SECONDS = {"d": 86400, "h": 3600}


def shown_count(text: str) -> float | None:
    """The seconds a display text counts with a unit letter glued to its number ("W 3d" is
    3 days, "d2" 2 days: an interval lamp), or None. A panel too narrow for "days" writes the
    letter; the manual's legend says what it counts, the display is how the user sees it."""
    found = _SHOWN_COUNT.findall(text)
    if len(found) != 1:
        return None
    number, letter, prefix, digits = found[0]
    return int(number or digits) * _LETTER_SECONDS[(letter or prefix).casefold()]


_UNIT_WORDS = {
    "v": "volt volts voltage",
    "a": "amp amps ampere amperes current",
    "hz": "hertz frequency",
}


def unit_words(unit: str) -> str:
    """The spoken names of a setting's electrical unit ("" for any other): "twelve volts"
    names the setting kept in V, though the quantity reader knows no electrical unit."""
    return _UNIT_WORDS.get(unit.strip().casefold(), "")
