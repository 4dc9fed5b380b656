"""The one row of levels a manual prints (a caption over "0 · 1 · … · 9 · P", or a display
legend's "1 … 9 | Heat setting" rows), for a unitless level of which nothing else is read."""

from __future__ import annotations

import itertools
import re

from apbot.read.text import Unit

_LEVELS_CAPTION_RE = re.compile(r"^(?:[\w-]+\s+)?(?:settings|levels)\s*:?$", re.IGNORECASE)
_LEVEL_RUN_RE = re.compile(r"^(\d{1,2})\s*(?:…|\.\.\.|-|–|—|to)\s*(\d{1,2})$")


def levels_list(units: list[Unit]) -> tuple[list[str], int] | None:
    """The manual's one printed list of levels, for a unitless setting of which nothing else is
    read: a caption ("Heat settings") over a row "0 · 1 · 2 … 9 · P", or a display legend's rows
    "| 1 … 9 | Heat setting |" with a "| 0 |" row below and a "| P | the level after 9 |" row
    above it. None when there is none or more than one."""
    found: list[tuple[list[str], int]] = []
    for i, unit in enumerate(units[:-1]):
        if unit.cells or not _LEVELS_CAPTION_RE.match(unit.text.strip()):
            continue
        row = units[i + 1].text.strip()
        items = [p.strip() for p in re.split(r"\s*[·•|,/]\s*", row) if p.strip()]
        digits = [int(x) for x in itertools.takewhile(str.isdigit, items)]
        tail = items[len(digits) :]
        steady = digits == list(range(digits[0], digits[0] + len(digits))) if digits else False
        if len(digits) >= 3 and steady and len(tail) <= 2 and all(len(t) <= 2 for t in tail):
            found.append((items, i + 1))
    for i, unit in enumerate(units):
        run = _LEVEL_RUN_RE.match(unit.cells[0].strip()) if len(unit.cells) >= 2 else None
        if not run or not re.search(r"\b(?:setting|level)s?\b", unit.cells[1], re.IGNORECASE):
            continue
        low, high = int(run.group(1)), int(run.group(2))
        if high - low < 2:
            continue
        rows = [u for u in units if u.cells and u.header == unit.header and len(u.cells) >= 2]
        below = [str(low - 1)] if any(u.cells[0].strip() == str(low - 1) for u in rows) else []
        after = re.compile(rf"\b(?:after|above|beyond|past)\s+{high}\b", re.IGNORECASE)
        above = [
            u.cells[0].strip()
            for u in rows
            if after.search(u.cells[1]) and re.fullmatch(r"[A-Za-z]{1,2}", u.cells[0].strip())
        ][:1]
        found.append(([*below, *map(str, range(low, high + 1)), *above], i))
    distinct = {tuple(f[0]) for f in found}
    return found[0] if len(distinct) == 1 else None
