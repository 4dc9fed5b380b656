"""How long a key must be held: "keep touching ALARM for 5 seconds", "hold TIMER 3 s", or a key
legend's press-and-hold column ("ALARM | sound off / on | 5 s: key lock on / off").

Why: a hold shorter than the one the appliance waits for is ignored, so a belief that holds every
key for a guessed 3 s can never reach a function behind a 5 s hold (a key lock, "regenerate now").
"""

from __future__ import annotations

import re
from collections import Counter

_UNIT = r"(?:s|sec|secs|second|seconds)\b"
_NUMBER = r"(\d{1,2}(?:[.,]\d)?)"
_HOLD = (
    r"(?:press\s+and\s+hold|touch\s+and\s+hold|hold\s+down|hold|holding|keep\s+touching"
    r"|keep\s+pressing|keep\s+pressed|long[- ]press)"
)
_ABOUT = r"(?:for\s+)?(?:about\s+|at\s+least\s+|approx\.?\s+|approximately\s+|around\s+)?"
_KEY = r"(?:\s+(?:key|button|pad|field|touch\s+field))?"
_ARROW = r"(?:\s*[▲▼△▽◀▶◄►↑↓])?"
_CELL_SPLIT = re.compile(r"\s{2,}|\s*[|│]\s*")
_CELL_SECONDS = re.compile(rf"^(?:{_HOLD}\s+)?{_ABOUT}{_NUMBER}\s*{_UNIT}", re.IGNORECASE)
_ROW_MARK = re.compile(r"^(?:\(\d{1,2}\)|\d{1,2}[.)]|[A-Z][.)]?)\s+")


def hold_seconds(lines: list[str], label: str) -> float | None:
    """The hold time the manual gives for the key labelled ``label``: the most often written
    one (the longer on a tie, since a longer hold still counts), or None when none is written."""
    if not label.strip():
        return None
    name = re.escape(label.strip()).replace(r"\ ", r"\s+")
    before = re.compile(
        rf"{_HOLD}\s+(?:the\s+)?(?<![\w]){name}(?![\w]){_KEY}\s*,?\s*{_ABOUT}{_NUMBER}\s*{_UNIT}",
        re.IGNORECASE,
    )
    after = re.compile(
        rf"(?<![\w]){name}(?![\w]){_KEY}\s*,\s*{_HOLD}\s+{_ABOUT}{_NUMBER}\s*{_UNIT}",
        re.IGNORECASE,
    )
    found: Counter[float] = Counter()
    for line in lines:
        for pattern in (before, after):
            for match in pattern.finditer(line):
                found[_number(match.group(1))] += 1
        row = _legend_row(line, label.strip())
        if row is not None:
            found[row] += 1
    if not found:
        return None
    return max(found, key=lambda s: (found[s], s))


def _legend_row(line: str, label: str) -> float | None:
    """A legend row that starts with the key (after a row mark such as "(6)" or "B") and
    gives a time in a later column: "REGEN   regenerate tonight   5 s: regenerate now"."""
    cells = [c for c in _CELL_SPLIT.split(line.strip().strip("│|").strip()) if c]
    for i, cell in enumerate(cells[:3]):
        bare = _ROW_MARK.sub("", cell) if cell.casefold() != label.casefold() else cell
        if bare.casefold() != label.casefold():
            continue
        for later in cells[i + 1 :]:
            match = _CELL_SECONDS.match(later)
            if match is not None:
                return _number(match.group(1))
        return None
    return None


def _number(text: str) -> float:
    return float(text.replace(",", "."))


def pair_hold_seconds(lines: list[str], first: str, second: str) -> float | None:
    """The hold time for two keys held at once: "Hold WARM ▲ and COOL ▼ together for 5
    seconds", "+ and − together 5 s", a legend's "ZONE + TIMER  Held together for 3 seconds"
    (either key named first); the most often written one, None when none is."""
    if not first.strip() or not second.strip():
        return None
    found: Counter[float] = Counter()
    # only lines naming both keys can match; most manuals have none, and the pattern is long
    named = [w.lower() for w in (*first.split(), *second.split())]
    lines = [line for line in lines if all(w in line.lower() for w in named)]
    if not lines:
        return None
    for a, b in ((first, second), (second, first)):
        one = re.escape(a.strip()).replace(r"\ ", r"\s+")
        two = re.escape(b.strip()).replace(r"\ ", r"\s+")
        keys = (  # (a key's printed arrow may follow its name: "WARM ▲ and COOL ▼")
            rf"(?:the\s+)?(?<![\w]){one}(?![\w]){_ARROW}{_KEY}\s*(?:and|\+|&)\s*"
            rf"(?:the\s+)?(?<![\w]){two}(?![\w]){_ARROW}{_KEY}"
        )
        pattern = re.compile(
            rf"(?:{_HOLD}\s+)?{keys}\s*,?\s*(?:(?:are\s+)?held\s+)?together\s*[,:]?\s*{_ABOUT}"
            rf"{_NUMBER}\s*{_UNIT}|{_HOLD}\s+{keys}\s+{_ABOUT}{_NUMBER}\s*{_UNIT}",
            re.IGNORECASE,
        )
        for line in lines:
            for match in pattern.finditer(line):
                found[_number(match.group(1) or match.group(2))] += 1
    if not found:
        return None
    return max(found, key=lambda s: (found[s], s))
