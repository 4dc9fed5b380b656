"""A lamp drawn as a symbol and named for its setting: "Mirror lamp ⇋ (lit when the design is
mirrored)", "the ❄ symbol of EXTRA COLD".

A panel often lights a small symbol for an on/off setting instead of printing a word, and the
legend gives the setting's name, "lamp" (or symbol, icon, indicator) and the symbol. The symbol
is then what the display shows while the setting is on; without it the agent reads the setting
as unreadable and keeps pressing its key.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from apbot.read.text import Unit

_GLYPH = r"([^\w\s()\[\]{}.,;:!?'\"/\\|*-]{1,3})"
_NOUNS = r"(?:lamp|light|symbol|icon|indicator|LED)"


def symbol_lamp(units: Sequence[Unit], label: str) -> tuple[str, int] | None:
    """The symbol of the setting's own lamp ("Mirror lamp ⇋" for MIRROR) and where it is said,
    or None."""
    if not label or not re.search(r"[A-Za-z]{3}", label):
        return None
    name = r"\s+".join(re.escape(w) for w in label.split())
    pattern = re.compile(rf"(?<![\w]){name}\s+{_NOUNS}\s+{_GLYPH}(?=\s|$)", re.IGNORECASE)
    for i, unit in enumerate(units):
        m = pattern.search(unit.text)
        if m:
            return m.group(1), i
    return None
