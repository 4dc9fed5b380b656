"""A range the same sentence goes on past: "1 to 9, or 1 and then 0 for level 10".

Split out of ``values.py`` (over 20 KB). A keypad manual writes the single-digit levels as a
range and then says how to type the one two-digit level above them; that level belongs to
the same range, so its top is the last level named, when it follows straight on.
"""

from __future__ import annotations

import re

# ", or …  for (level) 10" / ", or … to get (level) 10" right after the range
_GOES_ON_RE = re.compile(
    r"\s*,?\s*or\b[^.;]{0,40}?\b(?:for|to get|gives?|for a|for the)\s+"
    r"(?:(?:power\s+)?(?:level|setting|step|power)\s+)?(\d{1,3})\b(?!\s*(?:%|°|[a-z]))",
    re.IGNORECASE,
)


def further_top(text: str, end: int, high: float) -> float:
    """The range's top, raised to the next whole number when the sentence goes on with
    "or … for level <high + 1>" right after the range ending at ``end``."""
    m = _GOES_ON_RE.match(text, end)
    if m and high == int(high) and int(m.group(1)) == int(high) + 1:
        return high + 1
    return high
