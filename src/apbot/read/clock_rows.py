"""A row of clock times that trails off: "(07:00 → 07:30 → 08:00 …)".

A manual shows how a key steps a time of day by its first few times and an ellipsis with no
last time after it: the times go on at the same step round the whole day, so the setting is
every time of the day on that step, not the three printed. Only two-digit hours count
("07:00", a time of day as a clock shows it; "0:30 → 1:00 …" is a duration), and only when
nothing after the ellipsis ends the row ("5, 10, 15 … 60" gives its own last).
"""

from __future__ import annotations

import itertools
import re

from apbot.read.values import Range

_DAY = 24 * 3600
_TIME = re.compile(r"\d{2}:[0-5]\d")


def open_day_row(values: list[str], text: str) -> Range | None:
    """The whole day on the row's step when ``values`` are times of day printed in ``text``
    with an open ellipsis after the last one, else None."""
    if len(values) < 3 or not all(_TIME.fullmatch(v.strip()) for v in values):
        return None
    secs = [int(v[:2]) * 3600 + int(v[3:5]) * 60 for v in (v.strip() for v in values)]
    if any(s >= _DAY for s in secs):
        return None
    gaps = {b - a for a, b in itertools.pairwise(secs)}
    step = gaps.pop() if len(gaps) == 1 else 0
    if step <= 0 or _DAY % step:
        return None
    last = re.escape(values[-1].strip())
    if not re.search(rf"(?<![\d:]){last}\s*(?:…|\.\.\.)(?!\s*(?:→|,|-|–)?\s*\d)", text):
        return None
    return Range(0, _DAY - step, "s", step)
