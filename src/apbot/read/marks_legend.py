"""A chart's legend of marks ("● = option possible   – = not possible"), read as meanings.

Commercial charts print a symbol per cell and explain the symbols once, on a line of their
own above the chart. The same symbol means "offered" in one manual and "starts on" in
another (``● = reminder starts ON   ○ = … OFF``), and a cross is "not available" as often as
it is "selected", so a cell's mark is read through its own manual's legend.
"""

from __future__ import annotations

import re

# a symbol set apart as the head of a legend entry: no letter, digit, bracket or stop
_SYMBOL = r"[^\w\s\[\](){}.,;:'\"/|<>=+#]"
_ENTRY_RE = re.compile(rf"({_SYMBOL})(?:\s*[=:]\s*|\s+)([A-Za-z][^=]*)")
_NOT_RE = re.compile(
    r"\b(?:not?|n/a|none|unavailable|excluded|omitted|skipped|left out|without|cannot)\b", re.I
)


# "on" as a preposition ("available on this cycle", "depends on load") or both states named
# ("can be switched on or off") says nothing about how the option starts
_ON_WORD_RE = re.compile(r"\bon\s+(?!by\b|at\b|when\b|after\b|until\b|for\b|in\b|as\b)[a-z]", re.I)
_BOTH_RE = re.compile(r"\b(?:on\s*(?:/|or|and)\s*off|off\s*(?:/|or|and)\s*on)\b", re.I)


def _meaning(text: str) -> str:
    """What a legend entry says a mark stands for: on, off, no (not offered) or yes."""
    state = _ON_WORD_RE.sub(" ", _BOTH_RE.sub(" ", text))
    if re.search(r"\boff\b", state, re.I):
        return "off"
    if re.search(r"\bon\b", state, re.I):
        return "on"
    return "no" if _NOT_RE.search(text) else "yes"


def legend_meanings(text: str) -> dict[str, str]:
    """Symbol → meaning, from lines explaining two or more symbols, each symbol followed by a
    short explanation and set off from the next entry by a wide gap ("✓ = can be set    ✗ =
    not available", "● yes    – no"). A symbol explained two ways is left out."""
    out: dict[str, str] = {}
    clash: set[str] = set()
    for line in text.split("\n"):
        pieces = re.split(r"\s{2,}", line.strip())
        entries: list[tuple[str, str]] = []
        k = 0
        while k < len(pieces):
            piece = pieces[k]
            if len(piece) == 1 and k + 1 < len(pieces):  # "●  phase included": one entry
                piece = f"{piece} {pieces[k + 1]}"
                k += 1
            k += 1
            m = _ENTRY_RE.fullmatch(piece)
            if m and len(m.group(2).split()) <= 10:
                entries.append((m.group(1), _meaning(m.group(2))))
        if len(entries) < 2 or not any(ord(s) > 0x7F for s, _ in entries):
            continue
        for symbol, meaning in entries:
            if out.get(symbol, meaning) != meaning:
                clash.add(symbol)
            out[symbol] = meaning
    return {s: m for s, m in out.items() if s not in clash}


def read_mark(cell: str, meanings: dict[str, str]) -> str:
    """A cell led by a legend's mark with the mark told in words ("✗ (DELAY --)" → "no
    (DELAY --)", "●" → "on" where ● means "starts ON"); other cells as they are."""
    text = cell.strip()
    if text and text[0] in meanings and (len(text) == 1 or text[1] == " "):
        return f"{meanings[text[0]]}{text[1:]}"
    return cell


def _title(lines: list[str], k: int) -> bool:
    """A short line standing alone between blank lines, without a stop: a section's title."""
    text = lines[k].strip()
    alone = (k == 0 or not lines[k - 1].strip()) and (
        k + 1 >= len(lines) or not lines[k + 1].strip()
    )
    return bool(text) and alone and len(text.split()) <= 5 and not text.endswith((".", ":", ","))


def chart_legend(lines: list[str], first: int, last: int) -> dict[str, str]:
    """The meanings of the legend printed with a chart whose rows run from line ``first`` to
    ``last`` (0-based): above it up to its section's title, or just below it. A legend of
    another section (the display's "● lamp on   ○ lamp off") says nothing of this chart."""
    above: list[str] = []
    for k in range(min(first, len(lines)) - 1, max(first - 30, -1), -1):
        if legend_meanings(lines[k]):
            above.append(lines[k])
        elif _title(lines, k):
            break
    below: list[str] = []
    for k in range(last + 1, min(last + 6, len(lines))):
        if legend_meanings(lines[k]):
            below.append(lines[k])
        elif _title(lines, k):
            break  # the next chart's title: a legend under it is that chart's
    return legend_meanings("\n".join(above)) or legend_meanings("\n".join(below))
