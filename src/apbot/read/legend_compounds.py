"""A key's legend naming its setting by a compound of the key's one word: "☾ Backlight."
for ``light`` (the icon written as LIGHT), "NIGHT Nightlight." The setting is the compound,
as the manual's other sentences ("backlight 3" among the factory settings) and users say it.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder


def legend_compound(b: Builder, token: str, label: str, mentions: list[int]) -> str:
    """The compound noun a legend line of just the key and one capitalised word gives, when
    the word ends in the key's one word with three letters or more before it; else ""."""
    if not label or "_" in token or len(token) < 3:
        return ""
    line = re.compile(rf"^\W*{re.escape(label)}\s+([A-Z][a-z]{{5,20}})\s*[.:]?\s*$")
    for i in mentions:
        m = line.match(b.manual.units[i].text)
        if m and m[1].lower().endswith(token) and len(m[1]) >= len(token) + 3:
            return m[1].lower()
    return ""
