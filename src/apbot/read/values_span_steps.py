"""A range told as spans of amounts, each with the step one press or click makes inside it:
"Between 30 seconds and 10 minutes each press changes the time by 30 seconds. Between 10 and
99 minutes each press changes it by 1 minute." or "1 to 10 minutes in 1-minute clicks, then
10 to 120 minutes in 5-minute clicks".

values_stepped.py reads such spans written as clock times ("from 1:00 to 3:00 each click is
ten minutes") or as a flattened table ("1 – 12 h 1 h"); a manual as often writes the ends as
amounts with their unit in running prose or list items, each span its own sentence or item.
"""

from __future__ import annotations

import re

from apbot.read.values import NUM, UNIT, Range, is_time_unit, number, seconds, unit_name

_TO = r"\s*(?:–|—|-|to|and)\s*"
_PRESS = r"(?:press|touch|click|tap|turn|step|push)"
_STEP_NUM = r"(?:\d+(?:[.,]\d+)?|one|an?|two|five|ten|fifteen|twenty|thirty|half\s+an?)"

# "between 30 seconds and 10 minutes each press changes the time by 30 seconds"
_EACH_RE = re.compile(
    rf"\b(?:from|between)\s+({NUM})\s*({UNIT})?{_TO}({NUM})\s*({UNIT})(?![\w:])"
    rf"[^.;:]{{0,12}}?\beach\s+{_PRESS}\w*\b[^.;:\d]{{0,40}}?\b(?:is|by|adds|of)\s+"
    rf"({_STEP_NUM})\s*({UNIT})(?![\w:])",
    re.IGNORECASE,
)
# "1 to 10 minutes in 1-minute clicks", "10 - 120 min in steps of 5 min"
_IN_RE = re.compile(
    rf"(?<![\w:.])({NUM})\s*({UNIT})?{_TO}({NUM})\s*({UNIT})\s+in\s+"
    rf"(?:({_STEP_NUM})[\s-]*({UNIT})\s+(?:clicks|steps|presses|increments|intervals)"
    rf"|steps\s+of\s+({_STEP_NUM})\s*({UNIT}))(?![\w:])",
    re.IGNORECASE,
)


def _amount(word: str) -> float | None:
    word = re.sub(r"\s+", " ", word.lower())
    if word.startswith("half"):
        return 0.5
    return 1.0 if word in ("a", "an", "one") else number(word)


def find_span_steps(text: str) -> list[Range]:
    """Two or more spans, each with its step, the next starting where the last ends; in the
    spans' one unit, or in seconds where a time is told in seconds and minutes; else []."""
    found: list[tuple[float, str, float, str, float, str]] = []
    for m in sorted([*_EACH_RE.finditer(text), *_IN_RE.finditer(text)], key=lambda m: m.start()):
        g = m.groups()
        step_word, step_unit = (g[4], g[5]) if g[4] else (g[6], g[7])
        low, high, step = number(g[0]), number(g[2]), _amount(step_word)
        if low is None or high is None or step is None:
            return []
        high_unit = unit_name(g[3])
        found.append(
            (low, unit_name(g[1]) or high_unit, high, high_unit, step, unit_name(step_unit))
        )
    units = {u for f in found for u in (f[1], f[3], f[5])}
    timed = len(units) > 1 and all(is_time_unit(u) for u in units)
    if len(units) > 1 and not timed:
        return []
    pieces: list[Range] = []
    for low, low_unit, high, high_unit, step, step_unit in found:
        if timed:
            low, high = seconds(low, low_unit), seconds(high, high_unit)
            step = seconds(step, step_unit)
        unit = "s" if timed else high_unit
        if not low < high or (pieces and pieces[-1].high != low):
            break
        pieces.append(Range(low, high, unit, step))
    return pieces if len(pieces) >= 2 else []
