"""How a walk ends by itself: a pause without a key, said in its last step ("Wait 10 seconds
without touching a key") or in a note of its section ("If you press no key for 8 seconds, the
menu closes by itself") - not a key held for that long ("hold MODE for 2 seconds to save")."""

from __future__ import annotations

import re

from apbot.read.build import Builder

# "Do not touch any key for 5 seconds: the setting is stored", "stored after a few seconds"
_STORED_RE = re.compile(
    r"\b(?:for|after|wait)\s+(?:(\d+)|a few)\s+seconds?\b[^.]*|\bstored\b[^.]*\bseconds\b", re.I
)
# a key held for those seconds is no pause: "Press and hold MODE for 2 seconds to save",
# "hold MODE for 2 seconds; the display returns to …", "keep SET pressed for 3 seconds"
_HELD_FOR_RE = re.compile(r"\b(?:hold|holding|held|keep\s+\S+\s+pressed)\b[^.;:]*$", re.I)
# what a pause does at the end of a walk: "If you press no key for 8 seconds, the menu closes"
CLOSES_RE = re.compile(r"\b(?:closes?|stored|returns?|leaves?|exits?)\b", re.I)


def pause_seconds(text: str) -> float | None:
    """The seconds of a pause without a key after which the walk ends ("Do not touch any key
    for 5 seconds: the setting is stored"), not a key held that long."""
    for m in _STORED_RE.finditer(text):
        if not _HELD_FOR_RE.search(text[: m.start()]):
            return float(m.group(1) or 5)
    return None


def walk_timeout(b: Builder, end: str, at: int) -> float | None:
    """The pause after which the walk ends by itself: said in its last step ("Wait 10 seconds
    without touching a key"), else in a note of its section ("If you press no key for 8
    seconds, the menu closes by itself")."""
    pause = pause_seconds(end)
    if pause is not None:
        return pause
    units = b.manual.units
    for u in units[at : at + 25]:
        if u.heading != units[at].heading:
            break
        pause = pause_seconds(u.text)
        if pause is not None and u.step is None and CLOSES_RE.search(u.text):
            return pause
    return None
