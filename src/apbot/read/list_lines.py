"""A list of marks printed on a line and wrapped onto the next one.

A knob's marks drawn in a row ("100 W – DEFROST – 450 W – … – GRILL") often run past the
page width; the rest goes on the next line, which then starts with the separator
("– COMBI 1 – COMBI 2"). Read alone, the first line lacks the last marks and the second looks
like a bullet: this joins them back into one list.
"""

from __future__ import annotations

import re

from apbot.read.text import Manual
from apbot.read.value_lists import bare_list

# a separator a list's line can open or close with when the list runs on past it
_SEPARATOR_RE = re.compile(r"[–—·|/•-]")


def wrapped_list(manual: Manual, k: int) -> list[str] | None:
    """The bare list on unit ``k`` (see :func:`bare_list`), with the marks of the next line
    when that line carries the same list on: it follows at once, opens with a separator (or
    the first line ends with one), and is itself nothing but a list."""
    units = manual.units
    items = bare_list(units[k].text)
    if not items or k + 1 >= len(units):
        return items
    nxt = units[k + 1]
    if nxt.cells or nxt.line != units[k].line + 1:
        return items
    first = manual.lines[units[k].line - 1].rstrip()
    second = manual.lines[nxt.line - 1].lstrip()
    if not (_SEPARATOR_RE.match(second) or _SEPARATOR_RE.fullmatch(first[-1:])):
        return items
    more = bare_list(_SEPARATOR_RE.sub(" ", second, count=1)) or _few(nxt.text)
    if not more:
        return items
    return list(dict.fromkeys([*items, *more]))


def _few(text: str) -> list[str] | None:
    """One or two marks left for the wrapped line (bare_list wants three)."""
    parts = [p.strip() for p in re.split(r"\s[–—·|/•-]\s|\s{2,}", text) if p.strip()]
    parts = [p for p in parts if re.search(r"[^\W_]", p)]
    if 1 <= len(parts) <= 2 and all(len(p) <= 20 and len(p.split()) <= 3 for p in parts):
        return parts
    return None
