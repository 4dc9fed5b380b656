"""Legend items led by a lettered callout: "(a) Dog icon: …", "(b) Mode icon: …", "[F] DOG 1/2
slide switch", "[B] ▲ / [C] ▼ - level up / down". Apart from text.py's bullet shapes because a
lone "(a)" may also stand in a sentence ("fit the lid (a) first"): a line is an item only when
the line of the next or the previous letter of the same run stands at the same indent within a
few lines, the way a drawing's legend is set.
"""

from __future__ import annotations

import re

# one callout letter in round or square brackets, then the item ("(f)(g) ▲ ▼" a pair of keys)
CALLOUT_RE = re.compile(r"^(\s*)([(\[])([A-Za-z])[)\]](?:[(\[][A-Za-z][)\]])*\s+(?=\S)")
_LETTER_RE = re.compile(r"[(\[]([A-Za-z])[)\]]")
# a further callout after a wide gap: the parts of a drawing printed on one line
# ("[A] ⏻     [B] FN     [C] SET"), not one item naming two keys ("[B] ▲ / [C] ▼")
_DRAWN_RE = re.compile(r"\S\s{3,}[(\[][A-Za-z][)\]]")


def lettered_items(lines: list[str]) -> set[int]:
    """Indices of lines that start an item of a lettered legend: two or more items whose
    letters follow on, each at the same indent and bracket, at most three lines apart."""
    found: dict[int, tuple[int, str, int, int]] = {}
    for i, line in enumerate(lines):
        m = CALLOUT_RE.match(line)
        if m and not _DRAWN_RE.search(line):
            letters = [ord(x.lower()) for x in _LETTER_RE.findall(line)]
            found[i] = (len(m.group(1)), m.group(2), letters[0], max(letters))
    items: set[int] = set()
    for i, (indent, bracket, _first, last) in found.items():
        for j in range(i + 1, i + 4):
            if j in found and found[j][:3] == (indent, bracket, last + 1):
                items |= {i, j}
                break
    return items


def item_text(line: str) -> str:
    """The item without its callouts: "[B] ▲ / [C] ▼ - level up / down" → "▲ / ▼ - level up /
    down" (a callout left inside would stand between the keys and their job)."""
    m = CALLOUT_RE.match(line)
    rest = line[m.end() :] if m else line
    return re.sub(r"[(\[][A-Za-z][)\]] ?", "", rest).strip()  # (the gaps kept: "°C/°F   switches")
