"""Tables of fault codes, which are never a setting's values.

A long manual often prints its error codes right under the key they concern ("TIMER … The
display may show these codes:" then "Code | Meaning", "E1 | Sensor fault", "E2 | Overheat").
The rows look like any chart of a key's values, yet the codes name faults the appliance
reports, not positions a user picks. A table is read as such when every cell of its code
column is a short letters-and-digits code and its header, or most of its other cells, speak
of faults.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

_FAULT_CODE_RE = re.compile(r"[A-Za-z]{1,3}\s?-?\s?\d{1,3}")  # "E1", "F03", "Er 2", "E-4"
_FAULT_HEAD_RE = re.compile(
    r"\b(?:errors?|faults?|problems?|causes?|remed(?:y|ies)|solutions?|trouble\w*)\b", re.I
)
_FAULT_CELL_RE = re.compile(
    r"\b(?:fault\w*|errors?|fail\w*|overheat\w*|over-?temperature|malfunction\w*|abnormal\w*"
    r"|block(?:ed|age)|clogged|leak\w*|sensor|short[- ]circuit\w*|open[- ]circuit\w*|tilt\w*"
    r"|too (?:hot|high|low))\b",
    re.I,
)


def fault_table(header: Sequence[str], rows: Sequence[Sequence[str]], column: int = 0) -> bool:
    """Whether the table (``header`` and data ``rows``) lists fault codes in ``column``."""
    cells = [r[column].strip(" *") for r in rows if column < len(r)]
    if len(cells) < 2 or not all(_FAULT_CODE_RE.fullmatch(c) for c in cells):
        return False
    if any(_FAULT_HEAD_RE.search(h) for i, h in enumerate(header) if i != column):
        return True
    others = [" ".join(c for i, c in enumerate(r) if i != column) for r in rows]
    return 2 * sum(bool(_FAULT_CELL_RE.search(o)) for o in others) > len(others)
