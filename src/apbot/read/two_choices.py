"""Two amounts a key flips between are two choices, not a range: "SIZE toggles between 1.5 lb
and 2.0 lb", "the selector switches between 750 W and 1500 W" — while "can be set between 60 °C
and 100 °C" is a range. The verb says which: a key that toggles, switches, alternates or flips
between two amounts has those two settings only; so does a key that, as the subject, "chooses"
or "selects" between them ("the heat selector chooses between 750 W and 1500 W") — the third
person only: "you can choose between 1 and 12 hours" is a range.
"""

from __future__ import annotations

import re

from apbot.read.values import NUM

_TWO_CHOICES_RE = re.compile(
    r"\b(?:(?:toggl|switch|alternat|flip)\w*\s+(?:\w+\s+){0,3}?|(?:choose|select)s\s+)between\s+"
    rf"(?:the\s+)?{NUM}\s*[^\s\d,.;]{{0,4}}\s+and\s+(?:the\s+)?{NUM}(?![\d.]*\s*(?:to|-|–)\s*\d)",
    re.I,
)


def two_choices(text: str) -> bool:
    """Whether the sentence says a key flips between two amounts (its two choices)."""
    return bool(_TWO_CHOICES_RE.search(text))
