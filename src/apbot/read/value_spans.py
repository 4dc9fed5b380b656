"""Numbered positions written as a span inside a list of named ones.

A knob's positions are often printed "OFF, WARM, 1-5, SEAR" or "LOW · 1–6 · HIGH": the span
"1-5" stands for five positions, 1, 2, 3, 4 and 5, each a value of its own. A span only counts
as positions when its ends are whole numbers without a unit and a named position stands beside
it; a list of spans alone ("1-2, 3-4, 5-6") is groups of something, and "0-60 min" is a range.
"""

from __future__ import annotations

import re

_SPAN = re.compile(r"(\d{1,2})\s*(?:-|–|—|to)\s*(\d{1,2})")
_MAX_POSITIONS = 12  # more numbered positions than this in one span is a range, not detents


def _span(item: str) -> tuple[int, int] | None:
    m = _SPAN.fullmatch(item.strip())
    if not m:
        return None
    low, high = int(m.group(1)), int(m.group(2))
    return (low, high) if 0 < high - low <= _MAX_POSITIONS else None


def _named(item: str) -> bool:
    return bool(re.search(r"[A-Za-z]", item)) and not re.search(r"\d", item)


def expand_spans(values: list[str]) -> list[str]:
    """``values`` with each span of numbered positions written out ("1-5" → "1" … "5"), when a
    named position stands beside it; the list unchanged otherwise."""
    if not any(_named(v) for v in values) or not any(_span(v) for v in values):
        return values
    out: list[str] = []
    for value in values:
        span = _span(value)
        if span is None:
            out.append(value)
            continue
        out += [str(n) for n in range(span[0], span[1] + 1)]
    lowered = [v.lower() for v in out]
    return out if len(set(lowered)) == len(lowered) else values
