"""A key whose press switches something on, and whose next sentence says a second press
switches it off: "Press CHILL: the snowflake lamp lights and the water is cooled. Press again
to switch it off." The on/off is said in the sentence after the one naming the key, so it is
not among the key's own mentions; "again" ties it to the key just pressed.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder

_AGAIN_RE = re.compile(
    r"^(?:press|touch|tap|push)\s+(?:it\s+|the\s+key\s+|once\s+)?again\s+to\s+"
    r"(?:switch|turn)\s+(?:it\s+|this\s+)?off\b",
    re.IGNORECASE,
)


def toggled_again(b: Builder, key: ActionInfo, toggle_at: int | None) -> bool:
    """Whether the on/off read at ``toggle_at`` is a "Press again to switch it off" right after
    a sentence that names this key."""
    if toggle_at is None or toggle_at == 0 or key.skill != "press":
        return False
    text = b.manual.units[toggle_at].text
    sentences = re.split(r"(?<=[.!?])\s+", text)
    at = next((k for k, s in enumerate(sentences) if _AGAIN_RE.match(s)), None)
    if at is None:
        return False
    before = " ".join(sentences[:at]) if at else b.manual.units[toggle_at - 1].text
    labels = [b.labels[c].text for c in key.controls if c in b.labels and b.labels[c].text]
    return any(re.search(rf"(?<!\w){re.escape(lab)}(?!\w)", before) for lab in labels)
