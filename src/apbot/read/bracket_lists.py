"""Lists a quick reference or a one-line sentence writes with their ends marked: in brackets
after the key's name ("press MODE (SPOT → FLOOD → BOTH)"), a run of numbers that says where
it wraps ("1, 2, 3, 4, 5, and after 5 back to 1"), or letters stepped in the alphabet's order
with an ellipsis for those between ("A → B → … → F → A": banks, memories, slots; "A" is no
article there).

A quick-reference card names the key and then, in brackets, the values it steps through. The
words before the bracket are the key's name and the verb, never part of the first value, however
they are written (a key's name in capitals reads like one more capital word of the first item).
"""

from __future__ import annotations

import re
from itertools import pairwise


def bracket_opens(head: list[str]) -> list[str]:
    """The words of the first item from the last opening bracket on, the bracket dropped; an
    empty list where no bracket opens the list (or it opens at the first word)."""
    opened = max((k for k, w in enumerate(head) if w.startswith("(") and len(w) > 1), default=0)
    if opened == 0 or any(")" in w for w in head[opened:]):
        return []
    return [head[opened][1:], *head[opened + 1 :]]


# "1, 2, 3, 4, 5, and after 5 back to 1", "1, 2, 3 – after 3 it returns to 1"
_WRAPPED_RUN = re.compile(
    r"(?<![\w.])(?P<run>\d+(?:\s*,\s*\d+){2,})\s*,?\s*(?:and\s+|[–—-]\s*)?after\s+(?P<last>\d+)"
    r"\s*,?\s*(?:it\s+|the\s+\w+\s+)?(?:goes\s+|comes\s+|jumps\s+|steps\s+)?"
    r"(?:back|round|returns?)\s+to\s+(?P<first>\d+)\b",
    re.I,
)


def wrapped_run(text: str) -> list[str] | None:
    """A run of numbers that says where it wraps ("1, 2, 3, 4, 5, and after 5 back to 1"): the
    run, when the wrap leaves its last number for its first; None otherwise."""
    m = _WRAPPED_RUN.search(text)
    if m is None:
        return None
    run = re.split(r"\s*,\s*", m.group("run"))
    if run[-1] != m.group("last") or run[0] != m.group("first"):
        return None
    return run


# "A → B → … → F → A": single capitals joined by arrows, an ellipsis for the letters between
_LETTER_RUN = re.compile(r"(?<!\w)[A-Z](?:\s*(?:→|->)\s*(?:[A-Z](?!\w)|…|\.\.\.))+")


def letter_run(text: str) -> list[str] | None:
    """Letters stepped in the alphabet's order ("banks A → B → … → F → A", "memory A → B → C"),
    the ellipsis filled with the letters it skips and the wrap back to the first dropped; None
    unless every letter follows the one before (three at least)."""
    m = _LETTER_RUN.search(text)
    if m is None:
        return None
    parts = [p.strip() for p in re.split(r"\s*(?:→|->)\s*", m.group(0))]
    letters: list[str] = []
    for k, part in enumerate(parts):
        if part in ("…", "..."):
            if not letters or k + 1 >= len(parts) or len(parts[k + 1]) != 1:
                return None
            letters += [chr(c) for c in range(ord(letters[-1]) + 1, ord(parts[k + 1]))]
        else:
            letters.append(part)
    if len(letters) > 3 and letters[-1] == letters[0]:
        letters = letters[:-1]  # "… → F → A": round to the first
    return letters if lettered(letters) and all(c.isupper() for c in letters) else None


def lettered(values: list[str]) -> bool:
    """Values that are single letters in the alphabet's order (three at least): banks,
    memories or slots A, B, C …, a list of names however short."""
    return (
        len(values) >= 3
        and all(len(v) == 1 and v.isalpha() for v in values)
        and all(ord(b.upper()) - ord(a.upper()) == 1 for a, b in pairwise(values))
    )
