"""An amount whose step changes part way, told in one sentence: "500 to 2000 W in 100 W steps,
above 2000 W in steps of 250 W up to 3500 W", "20 to 60 % by 5 %, then by 10 % to 90 %".
Two pieces in one unit ([500, 2000, 100], [2000, 3500, 250]). Times that change step are read
by :func:`apbot.read.values.find_two_steps`; this is for the other units (watts, percent,
degrees, rpm)."""

from __future__ import annotations

import re

from apbot.read.values import NUM, UNIT, Range, is_time_unit, number, unit_name

_STEP = (
    rf"(?:in\s+({NUM})\s*-?\s*(?:{UNIT})?\s*(?:steps|increments)"
    rf"|(?:in\s+)?(?:steps?|increments?)\s+of\s+({NUM})\s*(?:{UNIT})?"
    rf"|by\s+({NUM})\s*(?:{UNIT})?)"
)
_PIECES_RE = re.compile(
    rf"(?<![\w.,])({NUM})\s*(?:{UNIT})?\s*(?:to|–|—|-)\s*({NUM})\s*({UNIT})(?!\w)\s*,?\s*{_STEP}"
    rf"\s*[,;]?\s*(?:and\s+|then\s+)*(?:(?:above|over|beyond|past|from)\s+({NUM})\s*(?:{UNIT})?"
    rf"\s*,?\s*)?{_STEP}\s*,?\s*(?:up\s+to|to|until)\s+({NUM})\s*(?:{UNIT})?(?!\w)",
    re.IGNORECASE,
)


def find_amount_pieces(texts: list[str]) -> tuple[list[Range], int] | None:
    """The two pieces of the first text that tells them, and that text's index (else None)."""
    for k, text in enumerate(texts):
        for m in _PIECES_RE.finditer(text):
            g = m.groups()
            unit = unit_name(g[2])
            if is_time_unit(unit):
                continue  # times: find_two_steps, which knows hours from minutes
            low, middle, top = number(g[0]), number(g[1]), number(g[10])
            first = number(next((x for x in g[3:6] if x), ""))
            then = number(next((x for x in g[7:10] if x), ""))
            said = number(g[6]) if g[6] else middle
            if None in (low, middle, top, first, then, said) or said != middle:
                continue
            assert low is not None and middle is not None and top is not None
            assert first is not None and then is not None
            if low < middle < top and 0 < first <= middle - low and 0 < then <= top - middle:
                return [Range(low, middle, unit, first), Range(middle, top, unit, then)], k
    return None
