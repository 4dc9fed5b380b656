"""Keys named only in quotes: "Press the 'Shape' key", "hold “Start/Pause” for 2 seconds".

Many manuals print a key's name in quotes and ordinary case, never in capitals; the reader finds
keys as printed names (capitals, a panel list). A quoted name whose words are exactly one of
the panel's keys (the action names, an honest input) is that key's printed name, so it is
written in capitals without the quotes, as a panel would print it. Quoted text that names no
key ("the display shows 'Err'") stays as it is.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

_QUOTED = re.compile(r"(?<!\w)(['‘\"“])([A-Za-z][A-Za-z0-9/+ &-]{0,24}?)(['’\"”])(?!\w)")
_PAIRS = {"'": "'", "‘": "’", '"': '"', "“": "”"}


def _words(text: str) -> tuple[str, ...]:
    return tuple(w for w in re.split(r"[^a-z0-9]+", text.lower()) if w)


def name_quoted_keys(text: str, keys: Sequence[str]) -> str:
    """``text`` with each quoted key name written in capitals, unquoted."""
    names = {_words(k.replace("_", " ")) for k in keys}
    names.discard(())

    def put(m: re.Match[str]) -> str:
        if _PAIRS.get(m.group(1)) != m.group(3) or _words(m.group(2)) not in names:
            return m.group(0)
        return m.group(2).upper()

    return _QUOTED.sub(put, text)
