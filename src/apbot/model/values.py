"""Values of appliance variables: piecewise ranges, time, units, and goal normalisation.

A goal value arrives as text ("30 min", "half an hour", "1:30", "Fifty percent") and must be
compared with a model value exactly. The paper compares strings loosely with an LLM; we instead
convert every value to one canonical form here, in one place, and compare canonical values.

Canonical forms:
    * discrete: the exact string from the variable's value list;
    * numeric: an ``int`` when integral, else a ``float`` rounded to 6 decimals;
    * time: a ``"HH:MM:SS"`` string (hours may exceed 23).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from decimal import Decimal
from functools import lru_cache

Number = int | float

# --- time -----------------------------------------------------------------------------------

_HMS = re.compile(r"^\s*(\d+):([0-5]?\d):([0-5]?\d)\s*$")
_TWO = re.compile(r"^\s*(\d+):([0-5]?\d)\s*$")


@lru_cache(maxsize=1 << 17)
def format_hms(seconds: int) -> str:
    """Canonical ``HH:MM:SS`` for a number of seconds.

    Cached: a repaired model rebuilds its time domains (a day in seconds is 86,400 values),
    and the benchmark's belief comparisons parse the same times again and again.

    >>> format_hms(5400)
    '01:30:00'
    """
    hours, rest = divmod(int(seconds), 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours:02d}:{minutes:02d}:{secs:02d}"


@lru_cache(maxsize=1 << 17)
def parse_hms(text: str) -> int:
    """Seconds in a strict ``HH:MM:SS`` string (the model's own notation for times).

    >>> parse_hms("00:01:30")
    90
    """
    match = _HMS.match(str(text))
    if not match:
        raise ValueError(f"{text!r} is not a time in HH:MM:SS form")
    hours, minutes, secs = (int(part) for part in match.groups())
    return hours * 3600 + minutes * 60 + secs


def format_time(seconds: int, style: str) -> str:
    """Render seconds the way an appliance display would, in the given style.

    >>> format_time(90, "mm:ss"), format_time(5400, "h:mm"), format_time(5400, "min")
    ('01:30', '1:30', '90 min')
    >>> format_time(45, "s")  # a short run time in seconds (a dryer's "45 s")
    '45 s'
    """
    hours, rest = divmod(int(seconds), 3600)
    minutes, secs = divmod(rest, 60)
    if style == "mm:ss":
        return f"{hours * 60 + minutes:02d}:{secs:02d}"
    if style == "h:mm":
        return f"{hours}:{minutes:02d}"
    if style == "hh:mm":
        return f"{hours:02d}:{minutes:02d}"
    if style == "min":
        return f"{int(seconds) // 60} min"
    if style == "h":
        return f"{seconds / 3600:g} h"
    if style == "s":
        return f"{int(seconds)} s"
    return format_hms(seconds)


# --- numbers ----------------------------------------------------------------------------------


def tidy_number(value: Number | Decimal | str) -> Number:
    """An ``int`` when the number is integral, else a float rounded to 6 decimals.

    >>> tidy_number("2.50"), tidy_number(3.0)
    (2.5, 3)
    """
    number = Decimal(str(value))
    if number == number.to_integral_value():
        return int(number)
    return round(float(number), 6)


def expand_ranges(ranges: Sequence[Sequence[Number]]) -> list[Number]:
    """All values of piecewise ``[from, to, step]`` ranges, in order, shared ends once.

    Decimal arithmetic keeps ``0.1`` steps exact; whole-number ranges (most of them, and
    every time range in seconds) take a fast path through ``range``.

    >>> expand_ranges([[0, 60, 10], [60, 120, 30]])
    [0, 10, 20, 30, 40, 50, 60, 90, 120]
    """
    values: list[Number] = []
    for start, stop, step in ranges:
        if not step > 0:
            raise ValueError(f"range [{start}, {stop}, {step}]: the step must be positive")
        if all(_whole(x) for x in (start, stop, step)):
            part: list[Number] = list(range(int(start), int(stop) + 1, int(step)))
            values.extend(part[1:] if values and part and part[0] == values[-1] else part)
            continue
        current, end, inc = Decimal(str(start)), Decimal(str(stop)), Decimal(str(step))
        while current <= end:
            value = tidy_number(current)
            if not values or value != values[-1]:
                values.append(value)
            current += inc
    return values


def _whole(number: Number) -> bool:
    return isinstance(number, int) or (isinstance(number, float) and number.is_integer())


# --- words and units ----------------------------------------------------------------------------

NUMBER_WORDS: dict[str, int] = {
    "zero": 0,
    "one": 1,
    "two": 2,
    "three": 3,
    "four": 4,
    "five": 5,
    "six": 6,
    "seven": 7,
    "eight": 8,
    "nine": 9,
    "ten": 10,
    "eleven": 11,
    "twelve": 12,
    "thirteen": 13,
    "fourteen": 14,
    "fifteen": 15,
    "sixteen": 16,
    "seventeen": 17,
    "eighteen": 18,
    "nineteen": 19,
    "twenty": 20,
    "thirty": 30,
    "forty": 40,
    "fifty": 50,
    "sixty": 60,
    "seventy": 70,
    "eighty": 80,
    "ninety": 90,
    "hundred": 100,
    "thousand": 1000,
    "a": 1,
    "an": 1,
    "single": 1,
    "couple": 2,
}
# the ten digits as words ("zero" … "nine"), for numbers read out one digit at a time
DIGIT_WORDS: dict[str, int] = {
    w: NUMBER_WORDS[w]
    for w in ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")
}
_WORD_NUMBERS = NUMBER_WORDS
_FRACTIONS = {"half": 0.5, "quarter": 0.25}
_NUMBER_TOKEN = r"\d+(?:[.,]\d+)?"


def words_to_number(text: str) -> float | None:
    """Read a number written in words ("forty five", "one and a half", "two hundred").

    Returns None when the text is not a number. A signed number ("-5", "−0.5") is read as
    such; a hyphen only joins words ("twenty-five"), so "1-2" is not a number.

    >>> words_to_number("forty five"), words_to_number("one and a half"), words_to_number("blue")
    (45.0, 1.5, None)
    """
    stripped = text.lower().strip().replace("\u2212", "-")  # a typographic minus sign
    if re.fullmatch(r"[+-]?" + _NUMBER_TOKEN, stripped):
        return float(stripped.replace(",", "."))
    if re.search(r"\d-|-\d", stripped):
        return None  # a range such as "1-2", or a sign inside a phrase
    tokens = [t for t in re.split(r"[\s-]+", stripped) if t and t != "and"]
    if not tokens:
        return None
    total, current, seen = 0.0, 0.0, False
    for token in tokens:
        if re.fullmatch(_NUMBER_TOKEN, token):
            current += float(token.replace(",", "."))
        elif token in _FRACTIONS:
            # "half an hour" -> 0.5; "one and a half" -> 1.5
            current += _FRACTIONS[token]
        elif token in ("hundred", "dozen"):
            current = (current or 1) * (100 if token == "hundred" else 12)
        elif token == "thousand":
            total += (current or 1) * 1000
            current = 0
        elif token in _WORD_NUMBERS:
            if token in ("a", "an") and seen:
                continue  # "one and a half": the "a" is an article
            current += _WORD_NUMBERS[token]
        else:
            return None
        seen = True
    return total + current


# unit alias -> (dimension, factor to the dimension's base unit)
_UNITS: dict[str, tuple[str, float]] = {}


def _units(dimension: str, factor: float, *aliases: str) -> None:
    for alias in aliases:
        _UNITS[alias] = (dimension, factor)


_units("time", 1, "s", "sec", "secs", "second", "seconds")
_units("time", 60, "min", "mins", "minute", "minutes", "m")
_units("time", 3600, "h", "hr", "hrs", "hour", "hours")
_units("mass", 1, "g", "gram", "grams", "gr")
_units("mass", 1000, "kg", "kilo", "kilos", "kilogram", "kilograms")
_units("mass", 453.59237, "lb", "lbs", "pound", "pounds")
_units("mass", 28.349523125, "oz", "ounce", "ounces")
_units("volume", 1, "ml", "millilitre", "millilitres", "milliliter", "milliliters")
_units("volume", 1000, "l", "litre", "litres", "liter", "liters")
# a pipette's or dosing pump's volume: "50 µL" (the micro sign, or the Greek mu)
_units("volume", 0.001, "µl", "μl", "microlitre", "microlitres", "microliter", "microliters")
_units("length", 1, "mm", "millimetre", "millimetres", "millimeter", "millimeters")
_units("length", 0.001, "µm", "μm", "micron", "microns", "micrometre", "micrometres", "mic")
_units("length", 10, "cm", "centimetre", "centimetres", "centimeter", "centimeters")
_units("power", 1, "w", "watt", "watts")
_units("power", 1000, "kw", "kilowatt", "kilowatts")
_units("temperature", 1, "°c", "c", "°", "deg", "degree", "degrees", "celsius", "degc")
_units("fahrenheit", 1, "°f", "f", "fahrenheit", "degf")  # affine to °C: never converted
_units("ratio", 1, "%", "percent", "pct", "per cent")
_units("speed", 1, "rpm")
_units("count", 1, "cup", "cups", "slice", "slices", "piece", "pieces", "serving", "servings")
_units("level", 1, "level", "lvl")


def unit_of(text: str) -> tuple[str, float] | None:
    """Dimension and factor of a unit name, or None if unknown.

    >>> unit_of("hrs"), unit_of("kW")
    (('time', 3600), ('power', 1000))
    """
    return _UNITS.get(text.strip().lower().rstrip("."))


def _split_quantities(text: str) -> list[tuple[float, str]] | None:
    """Split "1 h 30 min", "2hrs", "half an hour", "fifty percent" into (number, unit) pairs."""
    cleaned = text.strip().lower().replace("°c", " °c").replace("°f", " °f").replace("%", " %")
    cleaned = re.sub(r"(\d)([a-z°µμ])", r"\1 \2", cleaned)
    tokens = [t for t in re.split(r"[\s,]+", cleaned) if t]
    pairs: list[tuple[float, str]] = []
    words: list[str] = []
    for index, token in enumerate(tokens):
        next_is_unit = index + 1 < len(tokens) and unit_of(tokens[index + 1]) is not None
        if unit_of(token) is not None and (words or pairs or index > 0):
            if words:
                number = words_to_number(" ".join(words))
                if number is None:
                    return None
                pairs.append((number, token))
                words = []
            elif pairs and pairs[-1][1] == "":
                pairs[-1] = (pairs[-1][0], token)
            else:
                return None
        elif token in ("and", "of") and not next_is_unit:
            continue
        else:
            words.append(token)
    if words:
        number = words_to_number(" ".join(words))
        if number is None:
            return None
        pairs.append((number, ""))
    return pairs or None


def parse_quantity(text: str) -> tuple[float, str | None, float] | None:
    """A number with an optional unit: (value, dimension, factor). None when not a quantity.

    Several parts of one dimension add up ("1 h 30 min" is 5400 s).

    >>> parse_quantity("1 h 30 min")
    (5400.0, 'time', 1.0)
    >>> parse_quantity("half an hour")
    (1800.0, 'time', 1.0)
    >>> parse_quantity("40")
    (40.0, None, 1.0)
    """
    pairs = _split_quantities(str(text))
    if not pairs:
        return None
    if len(pairs) == 1 and pairs[0][1] == "":
        return pairs[0][0], None, 1.0
    dimension: str | None = None
    total = 0.0
    for number, unit in pairs:
        info = unit_of(unit) if unit else None
        if info is None:
            return None
        if dimension is not None and info[0] != dimension:
            return None
        dimension = info[0]
        total += number * info[1]
    return total, dimension, 1.0


def normalise_text(text: str) -> str:
    """Case- and punctuation-insensitive key for comparing discrete values.

    >>> normalise_text("  Quick-Wash  "), normalise_text("quick wash")
    ('quick wash', 'quick wash')
    """
    return re.sub(r"[\s_\-/]+", " ", str(text).strip().casefold()).strip()


MAX_HINT_OPTIONS = 2_000
"""Options compared for a "did you mean" hint; past that, only the ones sharing a first letter."""


def closest_matches(text: str, options: Iterable[str], limit: int = 3) -> list[str]:
    """The options most similar to ``text``, for "did you mean" hints.

    difflib compares ``text`` with every option; for a very long list (a 100,000-value domain)
    only the options that start like ``text`` are compared, so a hint never costs seconds.
    """
    import difflib

    word = str(text)
    candidates = [str(o) for o in options]
    if len(candidates) > MAX_HINT_OPTIONS:
        head = word[:1].casefold()
        candidates = [o for o in candidates if o[:1].casefold() == head][:MAX_HINT_OPTIONS]
    return difflib.get_close_matches(word, candidates, n=limit, cutoff=0.5)


def brief(value: object, limit: int = 60) -> str:
    """``repr(value)``, cut to ``limit`` characters: a message quotes what it was given
    without printing a 400-digit number or a pasted page.

    >>> brief("x" * 100, limit=10)
    "'xxxxxxxx…"
    """
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 1] + "…"


def preview(values: Sequence[object], limit: int = 8, quote: bool = True) -> str:
    """Values for a message: all of a short list, else the first few, the last and the count.

    A message must stay one readable line whatever the domain's size.

    >>> preview(["off", "on"])
    "['off', 'on']"
    >>> preview(list(range(10_000)), quote=False)
    '0, 1, 2, 3, 4, 5, 6, …, 9999 (10,000 in all)'
    """

    def show(items: Sequence[object]) -> list[str]:
        return [repr(v) if quote else str(v) for v in items]

    if len(values) > limit:
        body = ", ".join([*show(values[: limit - 1]), "…", *show(values[-1:])])
        text = f"[{body}]" if quote else body
        return f"{text} ({len(values):,} in all)"
    body = ", ".join(show(values))
    return f"[{body}]" if quote else body
