"""A key's own sentence stepping a range beats a list read only near it.

"Length of a burst — BURST key: … each further press adds one second, from 1 to 10 s" under a
heading that names BURST and TIME both ("TIMER OPERATION (INTERVAL AND BURST)"), TIME's list of
pauses printed a paragraph up ("10 s → 20 s → … → 180 s"): the arrows outrank prose, so BURST
took TIME's pauses. A range said with "each press" in a sentence naming the key is the key's
own; a list from a unit that does not name the key (reached through the heading) is not. Apart
from evidence.py (near its size line) because weighing the two readings is a job of its own."""

from __future__ import annotations

from apbot.read.shapes import Evidence


def own_press_range_wins(ev: Evidence, mentions: set[int]) -> bool:
    """Whether ``ev``'s range, stepped by each press in a sentence naming the key, should stand
    instead of its list, which no sentence naming the key gave."""
    return (
        ev.each_press_at is not None
        and ev.each_press_at == ev.range_at
        and ev.range_at in mentions
        and ev.values_at is not None
        and ev.values_at not in mentions
        and bool(ev.ranges)
    )
