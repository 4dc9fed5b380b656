"""Ranges told in parts that continue each other, read as one span.

"Addresses 1 to 127 are short ones; addresses 128 to 9999 are long ones", "channels 1–99 …,
channels 100–999 …": a manual splits a setting's whole count into named parts, each part
starting one past where the one before it ended. The setting takes every part; the first part
alone loses all values past its end. Parts with steps of their own, or that meet at one value
(0:05–1:00, then 1:00–10:00), are a piecewise scale and are read elsewhere.
"""

from __future__ import annotations

from apbot.read.values import Range


def abutting(first: Range, ranges: list[Range]) -> Range:
    """``first`` widened by every later range of its unit that starts one past its end
    (whole numbers, no step told on either)."""
    span = first
    for r in ranges:
        if (
            r.unit == span.unit
            and r.step is None
            and span.step is None
            and float(span.high).is_integer()
            and float(r.low).is_integer()
            and r.low == span.high + 1
            and r.high > r.low
        ):
            span = Range(span.low, r.high, span.unit, None)
    return span
