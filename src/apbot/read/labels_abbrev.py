"""A stepping key printed with the whole word its action name shortens: ``trans_up`` is the key
"TRANSPOSE +", ``temp_down`` "TEMPERATURE −".

Action names are terse and cut a long word to its first letters (trans, temp, prog), while the
panel and the manual print the word in full beside the sign. When no key prints the name as
the action spells it, the printed word that starts with the action's (three letters at least)
and carries the direction's sign is that key: its sections then speak of it, and the range
written there ("The range is -6 to +6 semitones") is its setting's.
"""

from __future__ import annotations

import re

from apbot.read.text import Manual


def abbreviated_signed_name(
    manual: Manual, name: str, signs: str, last: str
) -> tuple[str, int] | None:
    """The printing "<NAME…> <sign>" whose last word lengthens ``last`` (``name`` the escaped
    words as the action spells them, ``signs`` the escaped signs of its direction), where
    first seen; None when the shortened word is under three letters or nothing lengthens it."""
    if len(last) < 3 or not last.isalpha():
        return None
    pattern = re.compile(rf"(?<![A-Za-z0-9]){name}[A-Z]+\s?([{signs}])(?![\w+−–-])")
    for unit in manual.units:
        m = pattern.search(unit.text)
        if m:
            return m.group(0), unit.line
    return None
