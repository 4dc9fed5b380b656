"""A setting's ends told as the places where its key stops working.

"Nothing happens beyond 1 or 8", "At 0 and at 28 further clicks do nothing", "it stops at 5
and at 60": a manual often gives a stepped setting's range only by saying where the stepping
ends, not as "from 1 to 8". Those two figures are the setting's range; a range read earlier
from a sentence that does not name the key (another setting's "Addresses 1 to 127 …" a few
lines before) gives way to it.
"""

from __future__ import annotations

import re

from apbot.read.values import Range

_NUM = r"(-?\d+(?:\.\d+)?)"
# "beyond 1 or 8", "at 0 and at 28", "below 5 or above 60", "past 0 and 99"
_ENDS_RE = re.compile(
    rf"\b(?:at|beyond|past|below|under|above|over)\s+{_NUM}\s+(?:and|or)\s+"
    rf"(?:at\s+|beyond\s+|past\s+|above\s+|over\s+|below\s+)?{_NUM}(?!\d|[.:/]\d)",
    re.IGNORECASE,
)
# "stops at 0 and 28", "stops at 0 and at 28"
_STOPS_AT_RE = re.compile(
    rf"\bstops?\s+at\s+{_NUM}\s+and\s+(?:at\s+)?{_NUM}(?!\d|[.:/]\d)", re.IGNORECASE
)
# what the sentence says happens there: nothing
_NOTHING_RE = re.compile(
    r"\b(?:nothing\s+(?:happens|changes|more)|(?:do(?:es)?|changes?)\s+nothing|no\s+(?:further\s+)?effect"
    r"|(?:is|are)\s+ignored|stops?\b|no\s+further)",
    re.IGNORECASE,
)


def end_stops(text: str) -> Range | None:
    """The range whose two ends a sentence says the stepping stops at, else None."""
    m = _STOPS_AT_RE.search(text)
    if m is None:
        m = _ENDS_RE.search(text)
        if m is None or not _NOTHING_RE.search(text):
            return None
    low, high = sorted((float(m.group(1)), float(m.group(2))))
    return Range(low, high, "") if high > low else None
