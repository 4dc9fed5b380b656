"""A key's levels written as its own name and a number, each with what it means: "LIGHT 1
dimmest   LIGHT 2 dim   LIGHT 3 medium   LIGHT 4 brightest" (a key printed as an icon, its
name written where the icon stood, or a display that shows the key's name and the level).

Three or more such figures, counting up by one from 0 or 1, are the key's scale: a press steps
through them. Read only from a line that names the key; a single figure ("LIGHT 1 is shown")
or a jump ("L1, L3") is no scale.
"""

from __future__ import annotations

import re

from apbot.read.values import Range


def label_levels(text: str, label: str) -> Range | None:
    """The range 1–n (or 0–n) of the key's own levels written on the line, or None."""
    if not label or not re.search(r"[A-Za-z]", label):
        return None
    found = [
        int(m[1]) for m in re.finditer(rf"(?<!\w){re.escape(label)} ?(\d{{1,2}})(?![\d.,:/])", text)
    ]
    if len(found) < 3 or found[0] not in (0, 1) or found != list(range(found[0], found[-1] + 1)):
        return None
    return Range(float(found[0]), float(found[-1]), "", 1.0)
