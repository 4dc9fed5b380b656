"""The values a list leaves out with an ellipsis: "-16 → -17 → -18 → ... → -23 → -24".

A manual lists a long run of settings by its first few, an ellipsis and its last few; the run's
step is the one on both sides of the gap. Read item by item the list keeps only what it prints,
so a freezer set to -20 °C, or a timer at 4 h, is missing from the belief. Filled in, each gap
takes the values its neighbours step through (only where the text has the ellipsis, and only
when the step before the gap and the step after it agree — or, before the last item, the two
steps before the gap).
"""

from __future__ import annotations

import re

_ITEM_RE = re.compile(r"\s*([-−]?\d+(?:[.,]\d+)?)\s*(.*?)\s*")
# (the left item's unit may stand before the gap: "4 h … ──► 12 h"; an arrow may be drawn long)
_GAP = r"(?:\s*[^\W\d]{1,4}\b)?\s*[^\w\s]{0,3}\s*(?:\.\.\.|…)\s*[^\w\s]{0,3}\s*"
MAX_FILLED = 200


def filled(values: list[str], text: str) -> list[str]:
    """``values`` with each elided gap of ``text`` filled in, written as its left neighbour
    is (unchanged when no gap can be filled)."""
    parsed = [_ITEM_RE.fullmatch(v) for v in values]
    if len(values) < 4 or any(m is None for m in parsed) or not re.search(r"\.\.\.|…", text):
        return values
    figures = [m.group(1) for m in parsed if m]
    numbers = [float(f.replace(",", ".").replace("−", "-")) for f in figures]
    out: list[str] = [values[0]]
    for k in range(1, len(values)):
        out += _gap(values, figures, numbers, k, text)
        out.append(values[k])
    return out if len(out) - len(values) <= MAX_FILLED else values


def _gap(
    values: list[str], figures: list[str], numbers: list[float], k: int, text: str
) -> list[str]:
    """The values elided between items k-1 and k (none when the text shows no gap there)."""
    if k < 2 or k + 1 > len(values) or (k + 1 == len(values) and k < 3):
        return []
    before = numbers[k - 1] - numbers[k - 2]
    # the step after the gap, or before the last item's gap the step before the step before
    # ("0 → 2 → 3 → 4 … → 12": two equal steps say how the run goes on)
    after = numbers[k + 1] - numbers[k] if k + 1 < len(values) else numbers[k - 2] - numbers[k - 3]
    span = numbers[k] - numbers[k - 1]
    if not before or abs(before - after) > 1e-9 or abs(span) <= abs(before) + 1e-9:
        return []
    count = span / before
    if abs(count - round(count)) > 1e-6 or count <= 1:
        return []
    if not re.search(re.escape(figures[k - 1]) + _GAP + re.escape(figures[k]), text):
        return []
    m = _ITEM_RE.fullmatch(values[k - 1])
    suffix = f" {m.group(2)}" if m and m.group(2) else ""
    return [_figure(numbers[k - 1] + before * i) + suffix for i in range(1, round(count))]


def _figure(value: float) -> str:
    value = round(value, 6)
    return str(int(value)) if float(value).is_integer() else str(value)
