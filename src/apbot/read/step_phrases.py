"""Steps said as what one press or click does, in two more shapes real manuals share:
"Press ▲ to raise the level by 1, ▼ to lower it by 1" (an instruction whose purpose clause
says by how much) and "Each click changes the current by 5 A" (a click as the subject).
Apart from value_steps.py, whose other shapes these sit beside, so each can be read and tested.
"""

from __future__ import annotations

import re

from apbot.read.values import NUM, UNIT, number, unit_name

_VERBS = r"(?:raise|lower|increase|decrease|move|change|adjust|shift)"
# after the figure, a unit or nothing more of the phrase: "by 1, ▼ …", "by 5 A:", "by 1 Hz";
# never a count of something else ("by one step", "by one lamp (200 rpm)": no size)
_NO_SIZE = (
    rf"(?=\s*(?:{UNIT}(?!\w)|[,.;:)]|$|(?:and|or|to|until|at|per|each|every)\b"
    r"|[A-Z][A-Za-z]?\b))"
)
# "Press ▲ to raise the level by 1", "Press ► to raise it by 1 Hz" (a count needs no unit)
_PRESS_TO_BY_RE = re.compile(
    rf"^\W*(?:press|touch|tap|push|turn)\b[^.;]{{0,30}}?\bto\s+{_VERBS}\b[^.;,]{{0,25}}?"
    rf"\bby\s+({NUM}){_NO_SIZE}(?:\s*({UNIT}))?(?![\w/:.,]\d|\w)",
    re.I,
)
# "Each click changes the current by 5 A", "every press raises it by 0.5 °C"
_EACH_BY_RE = re.compile(
    rf"\b(?:each|every)\s+(?:press|click|turn|touch|detent|step|tap|notch)\s+{_VERBS}s\b"
    rf"[^.;,]{{0,30}}?\bby\s+({NUM}){_NO_SIZE}(?:\s*({UNIT}))?(?![\w/:.,]\d|\w)",
    re.I,
)


def said_step(text: str) -> tuple[float, str] | None:
    """The step one press or click makes, said in either shape: (number, canonical unit)."""
    for pattern in (_PRESS_TO_BY_RE, _EACH_BY_RE):
        m = pattern.search(text)
        if m and (value := number(m.group(1))):
            return value, unit_name(m.group(2))
    return None
