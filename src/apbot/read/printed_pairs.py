"""Values printed on the panel: two numbers beside a switch's name ("DOG 1/2") are its two
positions, not a range; a list each of whose items is led by its icon ("♪ tone") is of names.
Apart from evidence_values.py, which otherwise takes two numbers for a range's ends and keeps an
item as printed, because only the printed name's slash or the icons say so.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from apbot.read.text import Unit


def printed_pair(values: list[str], units: Sequence[Unit], at: int | None) -> bool:
    """``values`` stand joined by a slash right after a name in capitals in the unit they were
    read from ("DOG 1/2 slide switch"): the positions the key is printed with."""
    if at is None or len(values) != 2 or at >= len(units):
        return False
    joined = re.escape("/".join(values))
    return re.search(rf"\b[A-Z]{{2,}}\s+{joined}(?![\w/])", units[at].text) is not None


# one or two printed signs, a space, then the value's name in words; a sign is no letter of the
# Latin alphabet, digit or bracket (a Greek letter drawn as an icon, "ϟ", is a sign)
_ICON_LED_RE = re.compile(r"(\S{1,2})\s+([A-Za-z][A-Za-z -]{1,30})")


def _sign(text: str) -> bool:
    return all(
        not c.isdigit() and c not in "()[]'\"-" and (ord(c) >= 0x250 or not c.isalnum())
        for c in text
    )


def icon_led(values: list[str]) -> tuple[list[str], dict[str, str]] | None:
    """A list whose every item is the sign the display lights and the value's name ("♪ tone",
    "≋ vibration", "ϟ static"): the names, each shown by its own sign; else None. Icons on a
    panel stand for the value; the user names it in words."""
    found = [_ICON_LED_RE.fullmatch(v.strip()) for v in values]
    if len(values) < 2 or not all(m and _sign(m.group(1)) for m in found):
        return None
    signs = [m.group(1) for m in found if m]
    names = [m.group(2).strip().lower() for m in found if m]
    if len(set(signs)) != len(signs) or len(set(names)) != len(names):
        return None
    return names, dict(zip(names, signs, strict=True))
