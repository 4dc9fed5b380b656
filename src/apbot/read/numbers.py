"""Numbers, quantities, durations and clock times in an instruction, read offline.

An instruction writes the same setting many ways ("90 minutes", "an hour and a half",
"1 hr 30", "1.5 hrs"; "7:30 pm", "half past seven in the evening", "19:30"). This module turns
the text into tokens and finds every such phrase as a :class:`Mention` with its span, so the
goal parser can decide which variable each one sets. Nothing here knows about a model.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

from apbot.model.values import unit_of
from apbot.read.number_tokens import Number, Token, read_number

# --- mentions ----------------------------------------------------------------------------------


@dataclass(frozen=True)
class Mention:
    """A quantity in the text.

    ``kind``: ``duration`` (``value`` in seconds), ``clock`` (seconds after midnight; ``meridiem``
    says whether am/pm or a day part fixed the half of the day), ``quantity`` (``value`` in the
    base unit of ``dimension``), ``fahrenheit`` (degrees F), or ``number`` (no unit).
    """

    kind: str
    value: float
    start: int
    end: int
    dimension: str | None = None
    meridiem: bool = False
    words: bool = False
    unit: str = ""
    colon: bool = False  # written with a colon ("1:30"): a duration after "for"
    lead: str = ""  # the word just before
    zero_led: bool = False  # written with a leading zero ("cone 06"): not the same code as 6


TIME_UNITS = {
    "s": 1,
    "sec": 1,
    "secs": 1,
    "second": 1,
    "seconds": 1,
    "min": 60,
    "mins": 60,
    "minute": 60,
    "minutes": 60,
    "m": 60,
    "h": 3600,
    "hr": 3600,
    "hrs": 3600,
    "hour": 3600,
    "hours": 3600,
    "day": 86400,
    "days": 86400,
}
# words a bare hour follows when it is a time of day ("off AT 10 at night", "FROM 9 in the
# morning TO 7 in the evening")
_TIME_LEADS = frozenset(
    {"at", "by", "until", "till", "til", "to", "from", "and", "or", "before", "after", "around"}
) | frozenset({"about", "past", "-", "–", "through", "between", "since", "tonight"})
_DAY_PARTS_PM = ("afternoon", "evening", "tonight", "night")
_DAY_PARTS_AM = ("morning",)
_CLOCK_WORDS = ("am", "pm", "oclock")
_NOT_UNITS = {"a", "an", "m", "s", "c", "f", "l", "g", "h", "w"}  # only after a number


def _word(tokens: list[Token], k: int) -> str:
    return tokens[k].text if 0 <= k < len(tokens) else ""


def find_mentions(tokens: list[Token], skip: set[int] | None = None) -> list[Mention]:
    """Every duration, clock time, quantity and bare number in the tokens, left to right.

    ``skip`` holds token indices already explained (a value name such as "quick 20").

    >>> from apbot.read.number_tokens import tokenize
    >>> [(m.kind, m.value) for m in find_mentions(tokenize("ready by 7:30 pm, 1 hr 20"))]
    [('clock', 70200), ('duration', 4800.0)]
    """
    skip = skip or set()
    mentions: list[Mention] = []
    i = 0
    n = len(tokens)
    while i < n:
        if i in skip:
            i += 1
            continue
        found = _clock_at(tokens, i) or _duration_at(tokens, i) or _quantity_at(tokens, i)
        if found is not None and not any(k in skip for k in range(found.start, found.end)):
            mentions.append(replace(found, lead=_word(tokens, i - 1)))
            i = found.end
            continue
        i += 1
    return mentions


def _clock_at(tokens: list[Token], i: int) -> Mention | None:
    """ "7:30", "7:30 pm", "9 pm", "8 o'clock", "half past six", "a quarter to eight"."""
    w = _word(tokens, i)
    hour: int | None = None
    minute = 0
    end = i
    if w in ("midnight", "noon", "midday"):
        return Mention("clock", 0 if w == "midnight" else 12 * 3600, i, i + 1, meridiem=True)
    dotted = (
        re.fullmatch(r"\d{1,2}\.\d{2}", w) is not None
        and (
            _word(tokens, i - 1) in ("at", "by", "until", "till")
            or _word(tokens, i + 1) in ("am", "pm")
        )
        and (_word(tokens, i + 1) in ("am", "pm", "") or _unit_at(tokens, i + 1) is None)
        and _time_unit(tokens, i + 1) is None
    )  # "ready by 7.30", "to 9.30 pm" (a British clock time, not seven point three)
    minutes = _minutes_past(tokens, i)
    if minutes is not None:
        hour, minute, end = minutes
    elif re.fullmatch(r"\d{1,2}:\d{2}", w) or dotted:
        hour, minute = (int(x) for x in w.replace(".", ":").split(":"))
        end = i + 1
        if minute >= 60 or hour > 24:
            return None
    elif w in ("half", "quarter") or (w in ("a",) and _word(tokens, i + 1) == "quarter"):
        k = i + (1 if w != "a" else 2)
        past = _word(tokens, k)
        if past not in ("past", "to"):
            return None
        number = read_number(tokens, k + 1)
        named = _word(tokens, k + 1)
        if number is None and named in ("midnight", "noon", "midday"):
            # "half past midnight": 00:30, "a quarter past noon": 12:15
            number = Number(0 if named == "midnight" else 12, k + 1, k + 2, True)
        if number is None or number.value != int(number.value) or not 0 <= number.value <= 12:
            return None
        quarter = 15 if (w == "quarter" or w == "a") else 30
        hour = int(number.value)
        if past == "past":
            minute = quarter
        else:
            hour, minute = (hour - 1) % 24, 60 - quarter
        end = number.end
    else:
        number = read_number(tokens, i)
        if number is None or number.value != int(number.value) or not 0 <= number.value <= 24:
            return None
        if number.words and _word(tokens, i) in ("a", "an", "single", "half", "quarter"):
            return None
        following = _word(tokens, number.end)
        led = i == 0 or _word(tokens, i - 1) in _TIME_LEADS
        spoken = _spoken_minutes(tokens, number)
        if spoken is not None:  # "seven thirty in the morning", "at six forty-five"
            following = _word(tokens, spoken.end)
            if following in _CLOCK_WORDS or _day_part(tokens, spoken.end) is not None or led:
                number, minute = replace(number, end=spoken.end), int(spoken.value)
                following = "oclock" if following not in _CLOCK_WORDS else following
        said = None
        if led and number.value <= 12 and following != "at":  # "10 at night": below
            said = _day_part_span(tokens, number.end)
        if following not in _CLOCK_WORDS and said is not None:  # "at eight tonight"
            hour = int(number.value) % 12 + (12 if said[0] == "pm" else 0)
            return Mention("clock", hour * 3600, i, number.end + said[1], meridiem=True)
        if following not in _CLOCK_WORDS:
            # "10 at night": a bare hour followed by the night, after a word that leads a time
            # ("drag 8 at night": a bare number after a setting's name is its value)
            night = following == "at" and _word(tokens, number.end + 1) == "night"
            night = night and (i == 0 or _word(tokens, i - 1) in _TIME_LEADS)
            if night and (6 <= number.value <= 12 or 1 <= number.value <= 4):
                hour = {12: 0}.get(int(number.value), int(number.value))
                hour += 12 if 6 <= hour < 12 else 0  # "1 at night" is 1:00, "12 at night" 0:00
                return Mention("clock", hour * 3600, i, number.end + 2, meridiem=True)
            # "7 in the evening": a bare hour followed by a day part
            if following == "in" and _word(tokens, number.end + 1) == "the":
                part = _word(tokens, number.end + 2)
                if part in _DAY_PARTS_PM + _DAY_PARTS_AM and number.value <= 12:
                    hour = int(number.value)
                    if part in _DAY_PARTS_PM and hour < 12:
                        hour += 12
                    return Mention("clock", hour * 3600, i, number.end + 3, meridiem=True)
            return None
        hour = int(number.value)
        end = number.end
        # "nine o'clock" also covered; minute stays 0 (or the spoken minutes read above)
    assert hour is not None
    meridiem = False
    nxt = _word(tokens, end)
    if nxt == "oclock":
        end += 1
        nxt = _word(tokens, end)
    if nxt in ("am", "pm"):
        meridiem = True
        if hour > 12:
            return None
        if nxt == "pm" and hour < 12:
            hour += 12
        if nxt == "am" and hour == 12:
            hour = 0
        end += 1
    else:
        half = _day_part(tokens, end)
        if half is not None:
            meridiem = True
            if half == "pm" and hour < 12:
                hour += 12
            if half == "am" and hour == 12:
                hour = 0  # "ten to one in the morning": 00:50
    if hour > 24:
        return None
    colon = ":" in _word(tokens, i) or "." in _word(tokens, i)
    return Mention("clock", hour * 3600 + minute * 60, i, end, meridiem=meridiem, colon=colon)


def _spoken_minutes(tokens: list[Token], hour: Number) -> Number | None:
    """The minutes of a time said as two numbers in words, the hour then the minutes ("seven
    thirty", "six forty-five"): an hour 1-12 and minutes 10-59, both in words, no unit after."""
    if not hour.words or not 1 <= hour.value <= 12:
        return None
    minutes = read_number(tokens, hour.end)
    if minutes is None or not minutes.words or minutes.start != hour.end:
        return None
    if minutes.value != int(minutes.value) or not 10 <= minutes.value <= 59:
        return None
    if _unit_at(tokens, minutes.end) is not None or _time_unit(tokens, minutes.end) is not None:
        return None  # "seven thirty-second runs", "two fifteen minutes"
    return minutes


_PAST_MINUTES = frozenset({5, 10, 20, 25})
"""Minutes said before "past"/"to" an hour ("twenty past one"); a quarter and a half are read
on their own, and other counts before "to" are a range ("from 5 to 8")."""


def _minutes_past(tokens: list[Token], i: int) -> tuple[int, int, int] | None:
    """ "twenty past one", "ten to eight", "twenty-five past six": (hour, minute, end). Only
    five, ten, twenty and twenty-five in words (a clock face's words), since "5 to 8" is a
    range."""
    number = read_number(tokens, i)
    if number is None or not number.words or number.value not in _PAST_MINUTES:
        return None
    k = number.end + (_word(tokens, number.end) in ("minutes", "mins"))
    past = _word(tokens, k)
    if past not in ("past", "to") or _word(tokens, i - 1) in ("from", "between"):
        return None
    hour = read_number(tokens, k + 1)
    if hour is None or hour.value != int(hour.value) or not 1 <= hour.value <= 12:
        return None
    if _word(tokens, hour.end) != "oclock" and _unit_at(tokens, hour.end) is not None:
        return None  # "ten to twelve minutes"
    if _time_unit(tokens, hour.end) is not None:
        return None
    minute = int(number.value)
    if past == "past":
        return int(hour.value), minute, hour.end
    return (int(hour.value) - 2) % 12 + 1, 60 - minute, hour.end  # "ten to one": 12:50


def _day_part(tokens: list[Token], k: int) -> str | None:
    """ "in the evening", "this afternoon", "tomorrow morning", "tonight" just after a time."""
    part = _day_part_span(tokens, k)
    return part[0] if part is not None else None


def _day_part_span(tokens: list[Token], k: int) -> tuple[str, int] | None:
    """The half of the day a day part names, and the words it takes."""
    words = [_word(tokens, k + d) for d in range(3)]
    for size in (1, 2, 3):
        tail = words[size - 1]
        lead = words[: size - 1]
        if all(x in ("in", "the", "this", "tomorrow", "tonight", "at") for x in lead):
            if tail in _DAY_PARTS_PM:
                return "pm", size
            if tail in _DAY_PARTS_AM:
                return "am", size
    return None


def _time_unit(tokens: list[Token], k: int) -> tuple[int, int] | None:
    """(seconds per unit, tokens used) at k: "minutes", "hrs", "min.", "-minute"."""
    w = _word(tokens, k)
    used = 0
    if w == "-":
        used = 1
        w = _word(tokens, k + 1)
    if w in TIME_UNITS:
        return TIME_UNITS[w], used + 1
    return None


def _duration_at(tokens: list[Token], i: int) -> Mention | None:
    """A sum of number+time-unit parts: "2 hrs 30 mins", "an hour and a half", "1 hr 20",
    "a quarter of an hour", "half an hour", "three quarters of an hour", "a full hour"."""
    total = 0.0
    j = i
    parts = 0
    words = False
    last_unit = 0
    while True:
        k = j
        if parts and _word(tokens, k) == "and":
            k += 1
        number = read_number(tokens, k)
        value: float | None = None
        if number is not None:
            value = number.value
            k2 = number.end
            words = words or number.words
            # "a quarter of an hour", "half an hour", "three quarters of an hour"
            if number.value < 1 and _word(tokens, k2) in ("of", "an", "a"):
                k3 = k2 + (1 if _word(tokens, k2) == "of" else 0)
                if _word(tokens, k3) in ("an", "a"):
                    k3 += 1
                unit = _time_unit(tokens, k3)
                if unit is not None:
                    total += value * unit[0]
                    j = k3 + unit[1]
                    parts += 1
                    last_unit = unit[0]
                    continue
            if _word(tokens, k2) in ("full", "whole", "entire") and number.value == 1:
                k2 += 1
            unit = _time_unit(tokens, k2)
            if unit is not None and parts and unit[0] >= last_unit:
                break  # "a day, 24 hours" is said twice, not added up
            if unit is not None:
                total += value * unit[0]
                j = k2 + unit[1]
                parts += 1
                last_unit = unit[0]
                # "an hour and a half"
                if _word(tokens, j) == "and" and _word(tokens, j + 1) in ("a", "an"):
                    if _word(tokens, j + 2) == "half":
                        total += 0.5 * unit[0]
                        j += 3
                    elif _word(tokens, j + 2) == "quarter":
                        total += 0.25 * unit[0]
                        j += 3
                continue
            # "1 hr 20": a bare number after hours is minutes, after minutes seconds
            if parts and last_unit in (3600, 60) and not number.words and value < 60:
                following = _word(tokens, k2)
                if following not in _UNIT_LIKE:
                    total += value * (last_unit // 60)
                    j = k2
                    parts += 1
                    last_unit = last_unit // 60
            break
        break
    if not parts:
        return None
    return Mention("duration", total, i, j, dimension="time", words=words)


_UNIT_LIKE = {"%", "°", "°c", "°f", "degrees", "degree", "percent", "rpm", "w", "watts"}


def _quantity_at(tokens: list[Token], i: int) -> Mention | None:
    """A number with an optional non-time unit: "350 °F", "1.5 kW", "fifty percent", "2 lb";
    negative after "minus" or a sign ("minus 19", "at -18")."""
    number = _signed(tokens, i) or read_number(tokens, i)
    if number is None:
        return None
    if number.words and _word(tokens, i) in ("a", "an") and number.end == i + 1:
        # "a" / "an" alone is a number only before a unit ("a kilo")
        unit = _unit_at(tokens, number.end)
        if unit is None:
            return None
    j = number.end
    unit = _unit_at(tokens, j)
    if unit is None:
        counted = _word(tokens, j) if _word(tokens, j) in COUNT_NOUNS else ""
        said = _word(tokens, i)
        zero_led = j == i + 1 and len(said) > 1 and said[0] == "0" and said.isdigit()
        return Mention(
            "number", number.value, i, j, words=number.words, unit=counted, zero_led=zero_led
        )
    name, used = unit
    end = j + used
    if name in ("degrees", "degree", "°", "deg"):
        # "degrees Fahrenheit", "degrees C"
        follow = _word(tokens, end)
        if follow in ("fahrenheit", "f"):
            return Mention("fahrenheit", number.value, i, end + 1, "fahrenheit", words=number.words)
        said = "degrees"
        if follow in ("celsius", "c", "centigrade"):
            end += 1
            said = "°c"  # said in Celsius: a Fahrenheit dial converts it
        return Mention(
            "quantity", number.value, i, end, "temperature", words=number.words, unit=said
        )
    info = unit_of(name)
    assert info is not None
    if info[0] == "fahrenheit":
        return Mention("fahrenheit", number.value, i, end, "fahrenheit", words=number.words)
    return Mention(
        "quantity", number.value * info[1], i, end, info[0], words=number.words, unit=name
    )


# words a sign may follow: "at -18", "to -20", ", -21" (not "C-3", "2-6": a code, a span)
_SIGN_LEADS = frozenset({"", ",", "at", "to", "of", "is", "on", "from", "about", "around", "and"})


def _signed(tokens: list[Token], i: int) -> Number | None:
    """A negative number: "minus" and a number, or a hyphen straight before digits where no
    letter or number comes before it (the tokenizer keeps a spaced dash as a clause break)."""
    sign = _word(tokens, i)
    if sign not in ("minus", "-"):
        return None
    if sign == "-" and _word(tokens, i - 1) not in _SIGN_LEADS:
        return None
    number = read_number(tokens, i + 1)
    if number is None or (sign == "-" and number.words):
        return None
    return Number(-number.value, i, number.end, number.words)


COUNT_NOUNS = frozenset(
    {
        "slice",
        "slices",
        "piece",
        "pieces",
        "cup",
        "cups",
        "serving",
        "servings",
        "portion",
        "portions",
        "people",
        "persons",
        "bottles",
        "bags",
        "loaves",
        "eggs",
        "potatoes",
        "shirts",
        "items",
        "pizzas",
        "mugs",
    }
)
"""Nouns a count stands before ("two slices"): the number counts them, it is no setting's
value unless the setting is named by that noun."""


def _unit_at(tokens: list[Token], j: int) -> tuple[str, int] | None:
    """A unit name at token ``j`` (possibly after a hyphen: "750-gram", "one-kilo")."""
    used = 0
    w = _word(tokens, j)
    if w == "-":
        used = 1
        w = _word(tokens, j + 1)
    if w in ("°", "degrees", "degree", "deg"):
        return w, used + 1
    if w in TIME_UNITS:
        return None
    if w in ("level", "levels", "lvl", "cup", "cups", "slice", "slices", "piece", "pieces"):
        return None  # counts are read as bare numbers
    if w in ("serving", "servings"):
        return None
    if unit_of(w) is not None:
        return w, used + 1
    return None
