"""A stepping pair keeps a setting of its own when a sentence naming only the pair gives it a
range in a unit ("▲ and ▼ set how much fog the pump delivers, in steps of 10 %: from 10 % to
100 %"), though a key also borrows the pair ("after ADDR, the address").

Without this the pair went wholly to the key that opens another setting, and its own amount
was lost as soon as that key was read as an entry key (an ADDR read as a toggle had left the
pair free). Apart from roles_amounts.py (near its size line) because telling the pair's own
range from a borrowing key's is a job of its own."""

from __future__ import annotations

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.shapes import Evidence


def pair_keeps_range(
    b: Builder, pair_tokens: list[str], entry_keys: list[ActionInfo], evidence: dict[str, Evidence]
) -> bool:
    """Whether the pair's own sentence gives it a range with a unit that no entry key's range
    shares, in a unit of the manual naming none of the entry keys."""
    ev = b.evidence(pair_tokens)
    if not ev.ranges or not ev.ranges[0].unit or ev.range_at is None:
        return False
    unit = ev.ranges[0].unit
    if unit in ("s", "min", "h", "hmm"):
        return False  # (a time is what the keys borrowing the pair mostly set)
    if not all(t in b.labels and ev.range_at in b.labels[t].mentions for t in pair_tokens):
        return False
    for key in entry_keys:
        if any(c in b.labels and ev.range_at in b.labels[c].mentions for c in key.controls):
            return False  # ("Press TIME, then ▲ / ▼: 1 to 60 min": the key's range)
        if any(r.unit == unit for r in evidence[key.name].ranges or []):
            return False
    return True
