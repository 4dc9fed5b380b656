"""One item of a list of values: cleaned of leading words and marks, judged value-like, and the
list kept free of repeats.

Apart from ``value_lists`` because every list finder there (and the shapes ``find_list`` reads,
in ``value_list_shapes``) cleans and checks its items the same way.
"""

from __future__ import annotations

import re

from apbot.read.values import NUM, UNIT

# the colon ending a lead-in ("Order: LOW → HIGH"), not one inside a clock time ("0:30")
_LEAD_COLON = re.compile(r"(?<!\d):|:(?!\d)")


_STOP_WORDS = {"the", "a", "an", "your", "this", "that", "it", "you", "to", "is", "are", "of"}


def _clean_item(item: str) -> str:
    gloss = re.fullmatch(r"\s*[-–—]+\s*\(\s*([A-Za-z]+)\s*\)\s*", item)
    if gloss:  # "-- (off)": a dashed screen glossed by its word, the value is the word
        return gloss.group(1)
    item = re.sub(r"\(.*?\)", "", item)
    item = re.sub(r"^(?:back to|then|and|or|finally)\s+", "", item.strip(), flags=re.I)
    return item.strip(" .;:!?\"'“”‘’*_")


_PER_NAME = re.compile(r"[A-Za-z]\s*:\s*\d")  # "(HOT: 3, COLD: 2)": a value per name, no list


def _value_like(item: str, caps_context: bool) -> bool:
    if not item or len(item) > 24 or re.search(r"[()\[\]{}]", item):
        return False
    if _PER_NAME.search(item):
        return False
    ws = item.split()
    if len(ws) > 3 or ws[0].lower() in _STOP_WORDS:
        return False
    if re.fullmatch(rf"{NUM}\s*{UNIT}?", item, re.IGNORECASE):
        return True
    if caps_context:
        return item.upper() == item and any(c.isalpha() for c in item)
    return all(w[:1].isupper() or w[:1].isdigit() for w in ws) or len(ws) == 1


def _dedupe(items: list[str]) -> list[str]:
    seen: list[str] = []
    for item in items:
        if item.lower() not in (s.lower() for s in seen):
            seen.append(item)
    return seen
