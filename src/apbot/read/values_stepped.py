"""Ranges told in pieces on one line, each piece with its own step, the next starting where the
last ends: a range-and-step table flattened into text ("0:30 - 12:00 30 minutes 12:00 - 24:00
1 hour") or an arrow chart ("1 h → … → 12 h one hour per press 12 h → … → 24 h two hours").
Their own job: chart shapes read whole, apart from the single ranges and steps of values.py.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from apbot.read.values import (
    _DASH,
    _TIME,
    NUM,
    UNIT,
    Range,
    is_time_unit,
    number,
    seconds,
    unit_name,
)
from apbot.read.values_span_steps import find_span_steps

# the words a step of minutes or hours is counted in ("30 minutes", "2 hrs"), as written out
MINUTES_HOURS = r"minutes?|mins?|hours?|hrs?"

_STEPPED_PIECE_RE = re.compile(  # "0:30 – 12:00  30 minutes": a range, then its step
    # (or a table's row "| 0:30 to 5:00 | 30 seconds |", "0:00 to 5:00  in 30-second steps",
    # "from 0:10 to 1:00 in steps of 10 minutes")
    rf"(?<![\d:])({_TIME}){_DASH}({_TIME})(?![\d:])\s*(?:h\b)?\s*\|?\s*"
    r"(?:by\s+|in\s+(?:steps\s+of\s+)?)?"
    rf"(\d+(?:[.,]\d+)?|one|an?)[\s-]*({MINUTES_HOURS}|h|seconds?|secs?|s)\b",
    re.IGNORECASE,
)
_STEP_FIRST_PIECE_RE = re.compile(  # "in 15-minute steps between 0:15 and 2:00": step, then range
    r"\b(?:in|by)\s+(?:steps\s+of\s+)?(\d+(?:[.,]\d+)?|one|an?)[\s-]*"
    rf"({MINUTES_HOURS}|h|seconds?|secs?|s)(?:\s+(?:steps|increments))?\s+"
    rf"(?:from|between)\s+({_TIME}){_DASH}({_TIME})(?![\d:])",
    re.IGNORECASE,
)


_DIGITS = r"\d+(?:[.,]\d+)?"


_STEPPED_AMOUNT_PIECE_RE = re.compile(  # "1 – 12 h  1 h": a range in a unit, then its step
    rf"(?<![\w:.])({_DIGITS})\s*(?:{UNIT})?{_DASH}({_DIGITS})\s*({UNIT})\s+"
    rf"(?:by\s+|in\s+steps\s+of\s+)?({_DIGITS}|one|an?)\s*({UNIT})(?![\w:])",
    re.IGNORECASE,
)


def find_stepped_pieces(text: str) -> list[Range]:
    """Two or more ranges, each followed by its step, the next starting where the last ends:
    clock times in seconds ("Range Step 0:30 - 12:00 30 minutes 12:00 - 24:00 1 hour"), each
    told as the span a press covers ("from 0:00 to 1:00 each click is one minute; from 1:00
    to 3:00 each click is ten minutes") or amounts in their unit ("Range Step 1 – 12 h 1 h 12
    – 24 h 2 h"); else []."""
    pieces = _stepped_clock_pieces(text) or _each_press_pieces(text)
    # (or amounts in prose: "between 30 seconds and 10 minutes each press … by 30 seconds")
    return pieces or _stepped_amount_pieces(text) or find_span_steps(text)


_EACH_PRESS_PIECE_RE = re.compile(  # "from 1:00 to 3:00 each click is ten minutes"
    rf"\b(?:from|between)\s+({_TIME}){_DASH}({_TIME})\b[^.;:]{{0,12}}?\beach\s+"
    r"(?:press|touch|click|tap|turn|step)\w*\b[^.;:\d]{0,40}?\b(?:is|by|adds|of)\s+"
    r"(\d+(?:[.,]\d+)?|one|an?|two|five|ten|fifteen|twenty|thirty|half\s+an?)\s*"
    rf"({MINUTES_HOURS}|h)\b",
    re.IGNORECASE,
)
_STEP_WORDS = {"one": 1.0, "a": 1.0, "an": 1.0, "two": 2.0, "five": 5.0, "ten": 10.0}
_STEP_WORDS |= {"fifteen": 15.0, "twenty": 20.0, "thirty": 30.0}


def _each_press_pieces(text: str) -> list[Range]:
    """Spans of a clock time, each with what one press adds inside it, the next starting
    where the last ends: the steps of a timer told in list items, one span an item."""
    pieces: list[Range] = []
    for m in _EACH_PRESS_PIECE_RE.finditer(text):
        low, high = _hmm(m.group(1)), _hmm(m.group(2))
        word = re.sub(r"\s+", " ", m.group(3).lower())
        amount = 0.5 if word.startswith("half") else _STEP_WORDS.get(word) or number(word)
        if amount is None or not low < high or (pieces and pieces[-1].high != low):
            break
        pieces.append(Range(low, high, "s", seconds(amount, unit_name(m.group(4)))))
    return pieces if len(pieces) >= 2 else []


def _stepped_clock_pieces(text: str) -> list[Range]:
    found = _as_written(_STEPPED_PIECE_RE.finditer(text))
    if len(found) < 2:
        found = _as_written(_STEP_FIRST_PIECE_RE.finditer(text), step_first=True)
    # a clock stepped in seconds, or one past 24 ("5:00 to 30:00"), is minutes and seconds;
    # never one stepped in hours ("24:00 to 72:00 in 1-hour steps": a long delay's hours)
    steps = {unit_name(step_unit) for _lo, _hi, _amount, step_unit in found}
    min_sec = "s" in steps or (
        "h" not in steps and any(int(hi.split(":")[0]) > 24 for _lo, hi, _a, _u in found)
    )
    pieces: list[Range] = []
    for lo, hi, said, step_unit in found:
        low, high = _clock(lo, min_sec), _clock(hi, min_sec)
        amount = 1.0 if said.lower() in ("one", "a", "an") else number(said)
        if amount is None or not low < high or (pieces and pieces[-1].high != low):
            return pieces if len(pieces) >= 2 else []
        pieces.append(Range(low, high, "s", seconds(amount, unit_name(step_unit))))
    return pieces if len(pieces) >= 2 else []


def _as_written(
    found: Iterable[re.Match[str]], step_first: bool = False
) -> list[tuple[str, str, str, str]]:
    """Each piece's (low, high, step amount, step unit) as written, whichever came first."""
    out = []
    for m in found:
        g = m.groups()
        out.append((g[2], g[3], g[0], g[1]) if step_first else (g[0], g[1], g[2], g[3]))
    return out


def _stepped_amount_pieces(text: str) -> list[Range]:
    """A table of ranges and steps in one unit flattened into a line; the step may be told in
    a smaller time unit ("0.5 – 10 h 30 min") and is then converted to the range's."""
    pieces: list[Range] = []
    for m in _STEPPED_AMOUNT_PIECE_RE.finditer(text):
        low, high, unit = number(m.group(1)), number(m.group(2)), unit_name(m.group(3))
        word = m.group(4).lower()
        amount = 1.0 if word in ("one", "a", "an") else number(m.group(4))
        step_unit = unit_name(m.group(5))
        if amount is not None and step_unit != unit:
            both_times = is_time_unit(step_unit) and is_time_unit(unit)
            amount = seconds(amount, step_unit) / seconds(1, unit) if both_times else None
        joined = not pieces or (pieces[-1].high == low and pieces[-1].unit == unit)
        if low is None or high is None or amount is None or not low < high or not joined:
            break
        pieces.append(Range(low, high, unit, amount))
    return pieces if len(pieces) >= 2 else []


_ARROW = r"\s*(?:[-─—–=]*[►→>])\s*"


_END = r"(\d{1,2}:\d{2}|\d+(?:[.,]\d+)?\s*(?:h|hrs?|hours?|min|mins|minutes?|s|secs?|seconds?)\b)"


_ARROW_PIECE_RE = re.compile(  # "1 h → 2 h → … → 12 h   one hour per press", "0:00 ──► 1:00  10 s"
    rf"(?<![\d:.]){_END}{_ARROW}(?:(?:…|\.\.\.|{_END}){_ARROW})*{_END}\s+(?:by\s+)?"
    rf"({NUM}|an?)\s*(hours?|hrs?|h|minutes?|mins?|min|seconds?|secs?|s)\b",
    re.IGNORECASE,
)


def _arrow_end(text: str, seconds_clock: bool) -> float | None:
    """An end of an arrow piece in seconds: "12 h", "30 min", or a clock "10:00" (h:mm, or
    mm:ss when the chart's steps are seconds or its first figure passes 24)."""
    clock = re.fullmatch(r"(\d{1,2}):(\d{2})", text.strip())
    if clock:
        big, small = int(clock.group(1)), int(clock.group(2))
        return big * 60 + small if seconds_clock else big * 3600 + small * 60
    m = re.fullmatch(r"(\d+(?:[.,]\d+)?)\s*(\w+)", text.strip())
    value = number(m.group(1)) if m else None
    return None if m is None or value is None else seconds(value, unit_name(m.group(2)))


def find_arrow_pieces(text: str) -> list[Range]:
    """Two or more pieces of a time drawn as arrows, each with its step, the next starting
    where the last ends ("1 h → 2 h → … → 12 h one hour per press 12 h → 14 h → … → 24 h two
    hours per press", "0:00 ──► 1:00 10 seconds 1:00 ──► 10:00 30 seconds"), in seconds."""
    found = list(_ARROW_PIECE_RE.finditer(text))
    if len(found) < 2:
        return []
    clocks = [m.group(1) for m in found] + [m.group(3) for m in found]
    by_seconds = any(unit_name(m.group(5)) == "s" for m in found) or any(
        ":" in c and int(c.split(":")[0]) > 24 for c in clocks
    )
    pieces: list[Range] = []
    for m in found:
        low, high = _arrow_end(m.group(1), by_seconds), _arrow_end(m.group(3), by_seconds)
        amount = 1.0 if m.group(4).lower() in ("a", "an") else number(m.group(4))
        if low is None or high is None or amount is None or not low < high:
            break
        if pieces and pieces[-1].high != low:
            break
        pieces.append(Range(low, high, "s", seconds(amount, unit_name(m.group(5)))))
    return pieces if len(pieces) >= 2 else []


def _clock(text: str, min_sec: bool) -> int:
    """Seconds in a clock figure, read as m:ss or h:mm."""
    first, second = text.split(":")
    return int(first) * 60 + int(second) if min_sec else _hmm(text)


def _hmm(text: str) -> int:
    h, m = text.split(":")
    return int(h) * 3600 + int(m) * 60
