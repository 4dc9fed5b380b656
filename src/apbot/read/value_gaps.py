"""Gaps in a printed row of values, and its trailing unit.

"50, 55, 60 ... 95, 100", "P1 → P2 → … → P6", "2 h → 3 h → 4 h … → 12 h", "75 ◄► 80 ◄► …
250 mic": a row of values drawn in a manual skips what its steps make plain and may print its
unit once. Apart from value_lists.py, which finds the rows, because filling a row is a job of
its own (values_elided.py fills the gaps of a list already read, against the text).
"""

from __future__ import annotations

import re

from apbot.read.values import NUM, UNIT


def elision_apart(item: str) -> list[str]:
    """An item with the ellipsis of a gap after it ("4 h …"): the item, then the gap."""
    m = re.fullmatch(r"(.*\w)\s*(…|\.\.\.)", item)
    return [m.group(1), m.group(2)] if m else [item]


_CODED = re.compile(r"([A-Za-z]{1,4}\s?-?)(\d{1,2})")


def filled_codes(parts: list[str]) -> list[str]:
    """An ellipsis between two codes of one kind ("P1 → P2 → … → P6"): the codes it skips."""
    out: list[str] = []
    for i, part in enumerate(parts):
        if part not in ("…", "...") or not out or i + 1 >= len(parts):
            out.append(part)
            continue
        before, after = _CODED.fullmatch(out[-1]), _CODED.fullmatch(parts[i + 1])
        if before and after and before.group(1) == after.group(1):
            lo, hi = int(before.group(2)), int(after.group(2))
            if 1 < hi - lo <= 40:
                out += [f"{before.group(1)}{n}" for n in range(lo + 1, hi)]
                continue
        out.append(part)
    return out


_AMOUNT = re.compile(rf"({NUM})\s*({UNIT})?", re.IGNORECASE)


def filled_amounts(parts: list[str]) -> list[str]:
    """An ellipsis after an amount in an arrow run ("2 h → 3 h → 4 h … → 12 h", "1 → 2 → … →
    9"): the amounts it skips, on the step of the two before it."""
    out: list[str] = []
    for i, part in enumerate(parts):
        base = re.sub(r"\s*(?:…|\.\.\.)$", "", part)
        if base == part and part not in ("…", "..."):
            out.append(part)
            continue
        if base and base not in ("…", "..."):
            out.append(base)
        ends = [_AMOUNT.fullmatch(p) for p in (*out[-2:], *parts[i + 1 : i + 2])]
        if len(out) < 2 or i + 1 >= len(parts) or not all(ends):
            continue
        a, b, c = (float(m.group(1).replace(",", ".")) for m in ends if m)
        unit = next((m.group(2) for m in ends if m and m.group(2)), None)
        step = b - a
        if step > 0 and c > b and (c - b) / step <= 40 and abs((c - b) / step % 1) < 1e-6:
            k = 1
            while b + k * step < c - 1e-6:
                v = f"{b + k * step:g}"
                out.append(f"{v} {unit}" if unit else v)
                k += 1
    return out


def unit_tail(items: list[str]) -> list[str]:
    """Numbers in a row with a unit of their own after the last ("75 ◄► 80 ◄► … 250 mic"): the
    unit, short and in lower case, is the row's whatever it is; judge the numbers alone."""
    tail = re.fullmatch(rf"({NUM})\s+[a-zµ]{{1,4}}", items[-1]) if items else None
    bare = all(re.fullmatch(NUM, i) for i in items[:-1])
    return [*items[:-1], tail.group(1)] if tail and bare and len(items) >= 3 else items


_PROGRESSION_RE = re.compile(  # "50, 55, 60 ... 95, 100", "MENU 1, MENU 2 … MENU 15"
    r"(?<![\d.])(?:([A-Z]{2,12}) )?(\d+(?:\.\d+)?),\s*(?:\1 )?(\d+(?:\.\d+)?)"
    r"(?:,\s*(?:\1 )?\d+(?:\.\d+)?)*,?\s*(?:\.\.\.|…)\s*(?:(?:up )?to\s+)?"
    r"(?:(?:\1 )?\d+(?:\.\d+)?,\s*)*(?:\1 )?(\d+(?:\.\d+)?)(?!\d|\.\d)\s*([A-Za-z%°]{1,8})?"
)


def find_progression(text: str) -> list[str] | None:
    """Settings written as the first few, an ellipsis and the last ("50, 55, 60 ... 95, 100"):
    every one of them, the step being the first gap."""
    m = _PROGRESSION_RE.search(text)
    if not m:
        return None
    first, second, last = float(m.group(2)), float(m.group(3)), float(m.group(4))
    gap = second - first
    if gap <= 0 or last <= second or (last - first) / gap > 400:
        return None
    count = round((last - first) / gap)
    if abs(first + count * gap - last) > 1e-6:
        return None  # the last is off the step: no progression
    unit = m.group(5) if m.group(5) and re.fullmatch(UNIT, m.group(5), re.I) else ""
    return [f"{first + k * gap:g}" + (f" {unit}" if unit else "") for k in range(count + 1)]
