"""Clock-like ranges whose printed label says how to read them.

Split out of ``values.py`` (over 20 KB). A spec table or step writes a range as two clock
figures, "0:01 - 99:59", which the reader takes as hours and minutes; a label printed with
it — "(min:s)", "min/sec", "mm:ss" — says they are minutes and seconds instead.
"""

from __future__ import annotations

import re

_MIN_SEC_LABEL = re.compile(
    r"\s*[(\[]?\s*(?:mins?|minutes?|mm?)\s*[:/.]\s*(?:s|secs?|seconds?|ss)\s*[)\]]?(?![\w:])",
    re.IGNORECASE,
)


def minutes_and_seconds(text: str, end: int) -> bool:
    """Whether the clock range ending at ``end`` in ``text`` is labelled minutes:seconds."""
    return bool(_MIN_SEC_LABEL.match(text, end))


def clock_seconds(figure: str, min_sec: bool) -> int:
    """Seconds in a clock figure "m:ss" (``min_sec``) or "h:mm"."""
    first, second = figure.split(":")
    return int(first) * 60 + int(second) if min_sec else int(first) * 3600 + int(second) * 60
