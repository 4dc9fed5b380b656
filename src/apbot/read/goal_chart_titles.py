"""The title over a numbered chart, as a name of what the chart numbers.

A chart "No.  Name  Character" under the heading "KIT LIST" numbers the kits: the heading's
own words name the setting (``kit``) whose numbers the chart's rows give names to ("the jazz
kit" is kit 3), as a column heading ("No. | Stitch") does. Only a heading in capitals on a line
of its own, at most three lines above the chart's "No." line, and only its words of three
letters or more other than "list", "table", "chart".
"""

from __future__ import annotations

import re

_NUMBERED = re.compile(r"^\s*\|?\s*(?:No\.?|Nr\.?|#)\s*(?:\||\s{2,})\s*[A-Za-z]+")
_TITLE = re.compile(r"^\s*([A-Z][A-Z &/-]{2,40})\s*$")
_NOT_NAMES = frozenset({"list", "lists", "table", "tables", "chart", "charts", "overview"})
_ABOVE = 3


def chart_titles(manual: str) -> frozenset[str]:
    """The words of the capital headings right above "No." charts ("KIT LIST" -> kit)."""
    lines = manual.splitlines()
    found: set[str] = set()
    for index, line in enumerate(lines):
        if not _NUMBERED.match(line):
            continue
        for above in reversed(lines[max(0, index - _ABOVE) : index]):
            if not above.strip():
                continue
            title = _TITLE.match(above)
            if title:
                words = re.findall(r"[a-z]{3,}", title[1].casefold())
                found.update(w for w in words if w not in _NOT_NAMES)
            break
    return frozenset(found)
