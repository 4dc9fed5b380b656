"""What holding a start key switches, when the manual says so.

Holding START is guessed to stop the programme when the manual is silent, but many panels give
the long press a job of its own: "To switch AUTO OFF on: press and hold START/STOP for 3
seconds", "Hold START 2 s to turn KEEP WARM on or off". A sentence that holds the key and
switches a setting named in capitals on or off makes that setting a toggle of the hold.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder

# a setting printed in capitals, switched on or off ("switch AUTO OFF on", "turns KEEP WARM off")
_SWITCHED = re.compile(
    r"\b(?:[Ss]witch|[Tt]urn)(?:es|s|ed|ing)?\s+(?:the\s+)?"
    r"(?P<name>[A-Z][A-Z0-9-]+(?: [A-Z][A-Z0-9-]+){0,2})\s+(?:on|off)\b"
)

# where one clause ends and the next begins: a sentence's end, a semicolon, or "then" — "hold
# START to cancel heating, then turn the POWER off" switches POWER by hand, not by the hold
_CLAUSE_RE = re.compile(r"(?<=[.!?;])\s+|,?\s+then\b")


def held_named_switch(b: Builder, info: ActionInfo) -> tuple[str, int] | None:
    """The setting holding this key switches on or off, and the unit that says so; None when
    no clause both holds the key and switches a setting named in capitals. (Not
    ``roles_common.held_switch``, which reads a lower-case noun near the key's own legend.)"""
    if info.skill != "hold" or not info.controls or info.controls[0] not in b.labels:
        return None
    label = b.labels[info.controls[0]].text
    if not label:
        return None
    held = re.compile(
        rf"\bhold(?:\s+down)?\s+(?:the\s+)?{re.escape(label)}(?!\w)|"
        rf"(?<!\w){re.escape(label)}\s*\(?\s*(?:(?:press|touch|push)\s+and\s+)?hold",
        re.IGNORECASE,
    )
    for i, unit in enumerate(b.manual.units):
        for clause in _CLAUSE_RE.split(unit.text):
            if not held.search(clause):
                continue
            m = _SWITCHED.search(clause)
            if m and m.group("name").upper() != label.upper():
                return m.group("name"), i
    return None
