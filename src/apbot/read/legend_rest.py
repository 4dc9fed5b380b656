"""What a key's own legend line or row says after the key's printed name.

Two readings look for what a key's legend says of a press or a hold ("START - Push: start …",
"| FOOD | Touch: … | Touch and hold 3 s: … |"); both need the same lines and the same rest.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from apbot.read.build import Builder
from apbot.read.text import Unit

# what leads a legend line before the key's name: "(c)", "4", "⑥", "[6]"
_LEAD = r"^\W*(?:\(?\w\)|\[\w+\]|\d{1,2}[.)]?)?\s*"


def legend_rests(b: Builder, control: str) -> Iterator[tuple[int, str]]:
    """Each unit that mentions ``control``'s printed name, with what it says after the name
    ("" when the line is not led by it)."""
    label = b.labels[control].text
    if not label:
        return
    led = re.compile(rf"{_LEAD}{re.escape(label)}(?![\w])\s*[-–—:]?\s*(?P<rest>.*)$", re.I)
    for i in b.labels[control].mentions:
        yield i, _rest_of(b.manual.units[i], label, led)


def _rest_of(unit: Unit, label: str, led: re.Pattern[str]) -> str:
    """A plain line led by the name: the rest of it; a row: its cells after the name's cell,
    each a part ("| 4 | FOOD | Touch: … | Touch and hold …: … |")."""
    if not unit.cells:
        m = led.match(unit.text)
        return m.group("rest") if m else ""
    for k, cell in enumerate(unit.cells[:2]):
        if cell.strip(" *[]").upper() == label.upper():
            return "   ".join(unit.cells[k + 1 :])
    return ""
