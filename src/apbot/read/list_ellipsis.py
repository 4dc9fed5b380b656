"""The stops an ellipsis leaves out of a printed row of values.

A row drawn stop by stop often skips the middle: "1:00 → 2:00 → 3:00 … → 9:00 → 10:00",
"10 → 20 → 30 … 90". The stops it leaves out go on in the step just before it, so 3:00 … 9:00
is 4:00, 5:00 … 8:00 — not one jump of six. Without this the row reads as pieces with a step
the appliance never takes.
"""

from __future__ import annotations

import re
from collections.abc import Callable

_FIGURE = r"(\d{1,2}:\d{2}|\d+(?:[.,]\d+)?)"
_SKIP_RE = re.compile(
    rf"(?<![\d:.,]){_FIGURE}[^\d\n]{{0,12}}?(?:…|\.\.\.)[^\d\n]{{0,12}}?{_FIGURE}(?![\d:])"
)


def fill_ellipses(nums: list[float], said: str, value_of: Callable[[str], float]) -> list[float]:
    """``nums`` (sorted) with the stops each ellipsis of ``said`` skips filled in on the gap
    just below it; ``value_of`` turns a printed figure into the numbers' scale."""
    out = sorted(set(nums))
    for m in _SKIP_RE.finditer(said):
        try:
            low, high = value_of(m.group(1)), value_of(m.group(2))
        except ValueError:
            continue
        if low not in out or high not in out or high <= low:
            continue
        below = [n for n in out if n < low]
        step = round(low - below[-1], 6) if below else 0.0
        if step <= 0 or round((high - low) / step, 6) % 1 or (high - low) / step > 1000:
            continue
        count = round((high - low) / step)
        out = sorted(set(out) | {round(low + step * k, 6) for k in range(1, count)})
    return out
