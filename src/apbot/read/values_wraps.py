"""A setting's ends from the sentence that says where it wraps: "after 23:45 comes 00:00",
"one more press after 15 h sets the timer back to 0".

Manuals often give a setting's range only through its examples ("the factory times are 08:00
and 20:00") or its first and last listed value ("1, 2, 3 … up to 15 hours"), and say what
follows the top in a sentence of its own. That sentence names both ends: the value before the
wrap is the top, the one after it the bottom. A read range lying inside those ends is widened
to them (a clock then covers the whole day; a timer counting 1 … 15 takes its 0, "off").
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from apbot.read.values import UNIT, Range, number, unit_name
from apbot.read.values_labels import clock_seconds

if TYPE_CHECKING:
    from apbot.read.shapes import Evidence
    from apbot.read.text import Unit

_TIME = r"\d{1,2}:\d{2}(?![\d:])"
_FIGURE = rf"(?:{_TIME}|\d+(?:[.,]\d+)?)"
_SIDE_X = rf"(?P<x>{_FIGURE})(?:\s*(?P<xu>{UNIT})(?!\w))?"
_SIDE_Y = rf"(?P<y>{_FIGURE})(?:\s*(?P<yu>{UNIT})(?!\w))?"
_WRAP_RES = (
    # "after 23:45 comes 00:00 (again)", "After 23 h it comes back to 0 h", "after 23 comes 00"
    re.compile(
        rf"\bafter\s+{_SIDE_X}\s*,?\s+(?:it\s+|the\s+\w+\s+)?(?:comes|goes|jumps|changes|"
        rf"returns|is|follows)\s+(?:back\s+|again\s+|round\s+)?(?:to\s+)?{_SIDE_Y}",
        re.IGNORECASE,
    ),
    # "one more press after 2000 g sets the weight back to 0", "after 15 returns the timer to 0",
    # "After 15 h   back to 0 (off)"
    re.compile(
        rf"\bafter\s+{_SIDE_X}[^.;:\d]{{0,40}}?\b(?:back|returns?)\b[^.;:\d]{{0,24}}?\bto\s+"
        rf"{_SIDE_Y}",
        re.IGNORECASE,
    ),
)


# time passing, not a press past the top: "after 10 minutes without a key press the display
# goes back to 0", "after 2 hours of keep warm it returns to 0", "… falls back to 9"
_ELAPSED = re.compile(
    r"\b(?:without|if\s+no|no\s+(?:key|button|press)|inactiv\w*|idle|elapsed?|passe[sd]|later|"
    r"of\s+(?:cooking|operation|use|running|keep[- ]warm|standby|inactivity)|"
    # a boost that runs out: "after 10 minutes the power level falls back to 9"
    r"falls?|fell|drops?|dropped|reduced?|reduces|lowered|lowers)\b",
    re.IGNORECASE,
)


def find_wrap(text: str) -> Range | None:
    """The ends a wrap sentence names, bottom to top (clock times in seconds, unit ``s``), or
    None when the text names no wrap from a larger value to a smaller one (nor when it says
    time passed before the change: a time-out, not a wrap)."""
    for pattern in _WRAP_RES:
        for m in pattern.finditer(text):
            if _ELAPSED.search(m.group(0)):
                continue
            found = _ends(m)
            if found is not None:
                return found
    return None


def _ends(m: re.Match[str]) -> Range | None:
    x, y = m.group("x"), m.group("y")
    if (":" in x) != (":" in y):
        return None  # "after 23:30 … to 0": figures of two kinds
    if ":" in x:
        if m.group("xu") or m.group("yu"):
            return None
        top, bottom = clock_seconds(x, False), clock_seconds(y, False)
        return Range(bottom, top, "s") if bottom < top else None
    units = {unit_name(u) for u in (m.group("xu"), m.group("yu")) if u}
    if len(units) > 1:
        return None  # "after 10 minutes … back to 9": two quantities, no wrap of one setting
    high, low = number(x), number(y)
    if high is None or low is None or not low < high:
        return None
    return Range(low, high, units.pop() if units else "")


def widened(ranges: list[Range], wrap: Range, step: tuple[float, str] | None) -> list[Range]:
    """``ranges`` widened to the wrap's ends, when the ends hold them all and the units agree
    (a bare wrap takes the ranges' unit, unless those are clock times); else unchanged."""
    if not ranges or any(r.unit != ranges[0].unit for r in ranges):
        return ranges
    unit = ranges[0].unit
    if wrap.unit != unit and (wrap.unit or unit == "s"):
        return ranges
    low, high = min(r.low for r in ranges), max(r.high for r in ranges)
    if not (wrap.low <= low and high <= wrap.high) or (wrap.low, wrap.high) == (low, high):
        return ranges
    if step is not None and unit == "s":
        every = step[0] * {"s": 1, "min": 60, "h": 3600}.get(step[1], 0)
        if every <= 0 or (wrap.high - wrap.low) % every:
            return ranges  # the ends are not whole steps apart: one of them is misread
    first, last = ranges[0], ranges[-1]
    if len(ranges) == 1:
        return [Range(wrap.low, wrap.high, unit, first.step)]
    return [
        Range(wrap.low, first.high, unit, first.step),
        *ranges[1:-1],
        Range(last.low, wrap.high, unit, last.step),
    ]


_ITEM_RE = re.compile(r"\s*(\d+(?:[.,]\d+)?)\s*(.*?)\s*")


def with_bottom(values: list[str], wrap: Range) -> list[str]:
    """A listed count ("1, 2, 3 … up to 15 hours") whose wrap goes from its last value to a
    smaller one not listed ("after 15 back to 0"): that value first, written as the others."""
    parsed = [_ITEM_RE.fullmatch(v) for v in values]
    if not values or wrap.unit == "s" or any(m is None for m in parsed):
        return values
    numbers = [float(m.group(1).replace(",", ".")) for m in parsed if m]
    suffixes = {m.group(2) for m in parsed if m} - {""}  # ("0.5, 1, 1.5 … 24 h": one unit)
    if len(suffixes) > 1 or (wrap.unit and suffixes and unit_name(min(suffixes)) != wrap.unit):
        return values
    first = parsed[0]
    suffix = first.group(2) if first else ""
    if max(numbers) != wrap.high or wrap.low >= min(numbers):
        return values
    low = int(wrap.low) if float(wrap.low).is_integer() else wrap.low
    return [f"{low} {suffix}".strip(), *values]


def _day(wrap: Range, step: tuple[float, str] | None) -> Range:
    """The clock times a wrap names, in the step read when it is a whole number of seconds."""
    every = step[0] * {"s": 1, "min": 60, "h": 3600}.get(step[1], 0) if step else 0
    if every <= 0 or (wrap.high - wrap.low) % every:
        return Range(wrap.low, wrap.high, "s")
    return Range(wrap.low, wrap.high, "s", every)


def wrap_ends(ev: Evidence, units: list[Unit], context: list[int]) -> None:
    """Widen ``ev``'s range (or listed count) to the ends the first wrap sentence names: one
    of the few units right after where the range or list was read, else one of ``context``
    (the units about the control). With nothing read, a wrap between two clock times ("after
    23:30 comes 00:00") is the range itself: a time of day whose steps only were given."""
    following = [
        k
        for at in (ev.range_at, ev.values_at, ev.step_at)
        if at is not None
        for k in range(at, min(at + 4, len(units)))
        if units[k].heading == units[at].heading
    ]  # (the sentence after the list: "One more press after 15 h gives 0 again.")
    for i in [*following, *context]:
        wrap = find_wrap(units[i].text)
        if wrap is not None:
            if not ev.ranges and not ev.values:
                if wrap.unit == "s":  # "after 23:30 comes 00:00": a time of day, nothing else
                    ev.ranges, ev.range_at = [_day(wrap, ev.step)], i
                return
            ev.ranges = widened(ev.ranges, wrap, ev.step)
            ev.values = with_bottom(ev.values, wrap) if ev.values else ev.values
            return
