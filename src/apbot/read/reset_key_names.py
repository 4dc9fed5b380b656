"""A reset sentence whose only programme word is a key's printed name: "Hold MODE again to go
back to white" says what the MODE key does, not that choosing a mode resets the settings.

The words a reset sentence looks for ("mode", "programme", "menu") are also printed on keys. Set
in capitals as the key's own label, the word names the key: the sentence goes back to a light, a
screen or a view, and no choice of programme resets anything.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder


def key_named_only(b: Builder, text: str, group: re.Pattern[str]) -> bool:
    """Every word of ``group`` in ``text`` is a key's printed label in capitals."""
    found = [m.group(0) for m in group.finditer(text)]
    printed = {lab.text for lab in b.labels.values() if lab.text}
    return bool(found) and all(w.isupper() and w in printed for w in found)
