"""What holding a key switches, from the part of its legend kept for holding.

Key tables give one key two jobs: a column "Touch and hold" beside "Short touch" ("| MIST |
level 1 → 2 → 3 | 3 s: warm mist on / off |"), or a second line under the key's row ("NEEDLE
Short press: stop up or down" then "Hold for 2 seconds: twin-needle mode on/off"). The on/off
thing named there is what the hold switches: a toggle of its own, named after it.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.text import Unit

_SECONDS = r"(?:for\s+)?\d+(?:[.,]\d+)?\s*(?:s|sec|secs|seconds?)\b"
_HELD = re.compile(  # "Hold for 2 seconds: twin-needle mode on/off", "3 s: warm mist on / off"
    rf"^\W*(?:(?:(?:press|touch|push)\s+and\s+)?hold\s*(?:{_SECONDS})?|{_SECONDS})\s*:\s*"
    r"(?P<noun>[a-z][a-z -]{2,30}?)\s+(?:mode\s+)?(?:on\s*(?:/|or)\s*off|off\s*(?:/|or)\s*on)\b",
    re.IGNORECASE,
)


def _hold_cells(unit: Unit) -> list[str]:
    """A row's cells under a header for holding ("Touch and hold", "Long press")."""
    return [
        cell
        for head, cell in zip(unit.header, unit.cells, strict=False)
        if re.search(r"\bhold|\blong\b", head, re.IGNORECASE)
    ]


def held_toggle(b: Builder, key: ActionInfo) -> str:
    """The on/off thing holding this key switches, read from its legend's hold part; ""."""
    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return ""
    label = b.labels[key.controls[0]].text.upper()
    units = b.manual.units
    for i in b.labels[key.controls[0]].mentions:
        unit = units[i]
        if not label or not unit.text.lstrip(" *|-•").upper().startswith(label):
            continue  # only the key's own legend
        candidates = _hold_cells(unit) if unit.cells else []
        if not unit.cells:  # the legend's next line, when it names no key of its own
            candidates += [units[k].text for k in (i + 1, i + 2) if k < len(units)]
        for text in candidates:
            m = _HELD.match(text)
            if m and not re.search(r"\b(?:lock|key|appliance)\b", m.group("noun"), re.I):
                return m.group("noun").strip(" -").lower()
    return ""
