"""Where a list in brackets opens: "press MODE (SPOT → FLOOD → BOTH)".

A quick-reference card names the key and then, in brackets, the values it steps through. The
words before the bracket are the key's name and the verb, never part of the first value, however
they are written (a key's name in capitals reads like one more capital word of the first item).
"""

from __future__ import annotations


def bracket_opens(head: list[str]) -> list[str]:
    """The words of the first item from the last opening bracket on, the bracket dropped; an
    empty list where no bracket opens the list (or it opens at the first word)."""
    opened = max((k for k, w in enumerate(head) if w.startswith("(") and len(w) > 1), default=0)
    if opened == 0 or any(")" in w for w in head[opened:]):
        return []
    return [head[opened][1:], *head[opened + 1 :]]
