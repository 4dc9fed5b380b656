"""Clock-like ranges whose printed label says how to read them.

Split out of ``values.py`` (over 20 KB). A spec table or step writes a range as two clock
figures, "0:01 - 99:59", which the reader takes as hours and minutes; a label printed with
it — "(min:s)", "min/sec", "mm:ss" — says they are minutes and seconds instead.
"""

from __future__ import annotations

import re

_MIN_SEC_LABEL = re.compile(
    r"\s*[(\[]?\s*(?:mins?|minutes?|mm?)\s*[:/.]\s*(?:s|secs?|seconds?|ss)\s*[)\]]?(?![\w:])",
    re.IGNORECASE,
)


def minutes_and_seconds(text: str, end: int) -> bool:
    """Whether the clock range ending at ``end`` in ``text`` is labelled minutes:seconds."""
    return bool(_MIN_SEC_LABEL.match(text, end))


# a clock figure's reading said in words: "(minutes:seconds)", "mm:ss"; or, beside a list of
# them, its steps told in seconds ("the steps are 30 seconds"): h:mm times are told in minutes
# and hours, never in seconds
_MIN_SEC_SAID_RE = re.compile(r"\b(?:mins?|minutes?)\s*[:/]\s*(?:secs?|seconds?)\b|\bmm:ss\b", re.I)
# steps told in seconds ("the steps are 30 seconds", "adds 15 s", "in 10-second steps"), not a
# wait ("flashes for 5 seconds", "hold 3 seconds"), which any clock's text may name
_SECONDS_RE = re.compile(
    r"\b(?:steps?|increments?|intervals?|by|adds?)\b[^.;\d]{0,20}\d+\s*(?:s|secs?|seconds?)\b"
    r"|\b\d+[- ]?(?:s|secs?|seconds?)\s+(?:steps?|increments?|intervals?)\b",
    re.IGNORECASE,
)


def seconds_said(beside: list[str], about: list[str]) -> bool:
    """Whether a list of clock figures is minutes and seconds: the texts ``beside`` it tell its
    steps in seconds, or the texts ``about`` its setting label its figures so."""
    return any(_SECONDS_RE.search(t) or _MIN_SEC_SAID_RE.search(t) for t in beside) or any(
        _MIN_SEC_SAID_RE.search(t) for t in about
    )


def clock_seconds(figure: str, min_sec: bool) -> int:
    """Seconds in a clock figure "m:ss" (``min_sec``) or "h:mm"."""
    first, second = figure.split(":")
    return int(first) * 60 + int(second) if min_sec else int(first) * 3600 + int(second) * 60


# only a top written as a clock figure: "up to 99:59", "the longest setting is 99:59",
# "Longest: 13:00" (a field of a setting's description)
_CLOCK_TOP_RE = re.compile(
    r"\b(?:up to|at most|max(?:imum|\.)?(?:\s+(?:of|is))?|(?:longest|maximum)\b[\w ]{0,24}?\bis"
    r"|(?:longest|maximum)\s*:)"
    r"\s+(\d{1,2}:\d{2})(?![\d:])",
    re.IGNORECASE,
)


# a sentence stepping in seconds ("in 30-second steps", "steps of 10 s") sets minutes and
# seconds: an h:mm setting never moves by seconds
_SECOND_STEPS_RE = re.compile(
    r"\b\d+\s*-?\s*(?:s|secs?|seconds?)\s+(?:steps?|increments?)\b"
    r"|\b(?:steps?|increments?)\s+of\s+\d+\s*(?:s|secs?|seconds?)\b",
    re.IGNORECASE,
)


def clock_tops(text: str) -> list[tuple[int, int, bool]]:
    """Seconds of each top written as one clock figure ("up to 99:59"), where it is said, and
    whether it is minutes and seconds: so when labelled so or when it cannot be a time of day
    (30:00, 24:30); else h:mm, "up to 24:00" being a whole day."""
    out: list[tuple[int, int, bool]] = []
    for m in _CLOCK_TOP_RE.finditer(text):
        figure = m.group(1)
        first, second = (int(p) for p in figure.split(":"))
        min_sec = minutes_and_seconds(text, m.end()) or first > 24 or (first == 24 and second > 0)
        min_sec = min_sec or bool(_SECOND_STEPS_RE.search(text))
        if second < 60:
            out.append((clock_seconds(figure, min_sec), m.start(), min_sec))
    return out


# a clock setting told in whole minutes: "adds one minute", "in 1-minute steps", "one minute per
# press", or its span "1 to 10 minutes" — the figures "10:00", "1:00" it shows are then minutes
# and seconds (an h:mm setting steps by minutes as 0:01, never as 1:00)
_MINUTE_STEP_RE = re.compile(
    r"\b(?:adds?|steps?|moves?|increases?|by|of)\b[^.;\d]{0,20}\b(?:one|a|1)[- ]minute\b"
    r"|\b(?:one|1)[- ]minute\s+(?:steps?|increments?|per\s+press)\b",
    re.IGNORECASE,
)
_MINUTE_SPAN_RE = re.compile(
    r"\b\d{1,2}\s*(?:to|-|–|…)\s*(\d{1,2})\s*(?:whole\s+)?(?:minutes?|mins?)\b", re.IGNORECASE
)
_HOURS_RE = re.compile(r"\b(?:hours?|hrs?)\b|\d\s*h\b", re.IGNORECASE)


def whole_minutes_said(figures: list[str], texts: list[str]) -> bool:
    """Whether clock figures that all end in ":00" are minutes: the texts about the setting
    step it by one minute or span it in minutes up to the largest figure, and none of them
    speaks of hours."""
    firsts = [int(f.split(":")[0]) for f in figures if re.fullmatch(r"\d{1,2}:00", f.strip())]
    if not firsts or len(firsts) != len(figures) or any(_HOURS_RE.search(t) for t in texts):
        return False
    return any(
        _MINUTE_STEP_RE.search(t)
        or any(int(m.group(1)) == max(firsts) for m in _MINUTE_SPAN_RE.finditer(t))
        for t in texts
    )
