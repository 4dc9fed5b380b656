"""The key that starts the run when the manual names only a key that stops it: "MODE  Turn:
choose the function. Push: START the function." beside "CANCEL  Stops the running function".

A panel with a CANCEL or STOP key but no START key starts its work with another control, and
its legend line says so in the part kept for that way of touching it ("Push: START …", "press
to start"). Read by name only, the stop key was the run's one way and "running" could never be
reached; the model checker then made the stop key a toggle of its own, a setting named after
the action ("press_cancel") that drew the user's words away. The legend line led by the key's
printed name (a line, or a table row with the name in its first cells) is its own.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.legend_rest import legend_rests

# the part of a legend line for pressing: "Push: START the function", "press to start"
_PRESS_STARTS = re.compile(
    r"^(?:(?:short\s+)?(?:push|press|touch|tap|click)(?:\s+(?:it|once|briefly))?\s*(?::|\s+to)"
    r"|(?:a\s+)?(?:short\s+)?(?:push|press)\s*:)\s*(?:starts?|begins?)\b(?!\s*(?:time|delay))",
    re.IGNORECASE,
)
_PARTS = re.compile(r"(?<=[.;])\s+|\s{3,}")


def legend_start(b: Builder, info: ActionInfo) -> int | None:
    """The unit of the key's own legend line whose part for pressing says it starts; else
    None (a held key, or a key of more than one control, is not read)."""
    if info.skill != "press" or len(info.controls) != 1 or info.controls[0] not in b.labels:
        return None
    for i, rest in legend_rests(b, info.controls[0]):
        if any(_PRESS_STARTS.match(part.strip()) for part in _PARTS.split(rest)):
            return i
    return None
