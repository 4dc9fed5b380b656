"""The low end of an amount said only as "up to": "To allow temperatures up to 45.0 °C".

"Up to" says how far a setting goes, not where it starts: read alone it is a range from 0. A
manual often states the whole range in another sentence ("can be set from 30.0 °C to 40.0 °C",
a specification row "45–100 °C"); that sentence's low end is the setting's. Times keep their
0: a timer said "up to 12 h" counts from nothing (0 is off), and a shorter time range near it
("1 – 60 min") is often another stage's.
"""

from __future__ import annotations

from apbot.read.values import UPTO_RE, Range, is_time_unit, number, unit_name


def stated_low(found: Range, text: str, named: tuple[Range, int] | None) -> Range:
    """``found``, read from ``text``, with the low end of the range ``named`` for the setting
    elsewhere when ``found`` is an "up to" amount from 0 and that range (same unit, above 0,
    not past the top) lies in it; else ``found`` as it is."""
    if (
        named is None
        or found.low != 0
        or found.unit in ("", "s", "hmm")
        or is_time_unit(found.unit)
    ):
        return found
    said = any(
        number(m.group(1)) == found.high and unit_name(m.group(2)) == found.unit
        for m in UPTO_RE.finditer(text)
    )
    r = named[0]
    inside = r.unit == found.unit and 0 < r.low < r.high <= found.high
    return Range(r.low, found.high, found.unit, found.step) if said and inside else found
