"""A run of display codes said by its two ends: "Press ▲ / ▼: CA 1 … CA 5".

Panels show a numbered setting with a short label before the figure (CA 1, P3, CH 07); a step
that presses the stepping pair often gives the run by its first and last code with an ellipsis
or "to" between them. The figures are the setting's range, in steps of one. Read only in a step
of the pair right after the key that opens the setting (``evidence``), where the codes can only
be that setting's. Apart from values.py because a code's label is no unit."""

from __future__ import annotations

import re

from apbot.read.text import Unit
from apbot.read.values import Range

_SPAN = re.compile(
    r"(?<![\w.])(?P<p>[A-Z]{1,3})(?P<s> ?)(?P<a>\d{1,3})\s*(?:…|\.\.\.|to|–|—)\s*"
    r"(?P=p)(?P=s)(?P<b>\d{1,3})(?![\w.])"
)


def code_span(text: str) -> Range | None:
    """The range of the one run of codes ``text`` names by its ends ("CA 1 … CA 5": 1–5), or
    None (no such run, or runs of two labels)."""
    found = [m for m in _SPAN.finditer(text) if int(m.group("a")) < int(m.group("b"))]
    if len(found) != 1 or int(found[0].group("b")) - int(found[0].group("a")) > 99:
        return None
    return Range(float(found[0].group("a")), float(found[0].group("b")), "", 1.0)


_NAMED_SPAN = re.compile(
    r"\b(?P<noun>[A-Za-z]{4,})\s*\(\s*(?P<a>\d{1,5})\s*(?:…|\.\.\.)\s*(?P<b>\d{1,5})\s*\)"
)


def named_span(text: str, own_words: set[str]) -> Range | None:
    """A bare span in brackets right after the setting's own noun ("Setting the DMX start
    address (1 … 512):" for ADDR): its range. A bare "1 … 10" elsewhere may be a row of
    digits, so only a noun sharing its first four letters with the key's name lends it."""
    for m in _NAMED_SPAN.finditer(text):
        noun = m.group("noun").lower()
        if not any(len(w) >= 4 and noun[:4] == w[:4] for w in own_words):
            continue
        low, high = int(m.group("a")), int(m.group("b"))
        if low < high:
            return Range(float(low), float(high), "", None)
    return None


def led_span(
    units: list[Unit], mentions: set[int], own_words: set[str]
) -> tuple[Range, int] | None:
    """The :func:`named_span` of a line that leads the steps naming the key ("Setting the DMX
    start address (1 … 512):" then "1. Press ADDR."), and where it stands."""
    for i in sorted(mentions):
        k = i - 1
        if k < 0 or units[k].heading != units[i].heading:
            continue
        if not units[k].text.rstrip().endswith(":") or units[k].cells:
            continue
        found = named_span(units[k].text, own_words)
        if found is not None:
            return found, k
    return None
