"""A number typed on the keypad takes every whole number of its range.

"Every locomotive has an address from 1 to 9999 … type the number and press ENTER": a setting
keyed in digit by digit is not stepped, so any whole number between its ends can be typed. With
no step told, the builder's guessed step (a twentieth of the span, 500 for 1–9999) left the
read model without 47 or 2301, and a goal naming one had nothing to reach.
"""

from __future__ import annotations

from typing import Any

from apbot.read.shapes import Evidence


def typed_every_whole(spec: dict[str, Any], ev: Evidence, keyed: Any) -> None:
    """Give a number typed on the keypad (``entry`` number, its range read from the manual,
    no step told) step 1 from its read low to its read high."""
    if spec.get("type") != "numeric" or spec.get("entry", {}).get("format") != "number":
        return
    if keyed or len(ev.ranges) != 1 or ev.ranges[0].step is not None:
        return
    r = ev.ranges[0]
    if not (float(r.low).is_integer() and float(r.high).is_integer()) or r.high <= r.low:
        return
    if r.unit and spec.get("unit") not in (None, r.unit):
        return  # (read in another unit than the spec keeps: leave the builder's reading)
    spec["ranges"] = [[int(r.low), int(r.high), 1]]
