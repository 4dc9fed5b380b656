"""A short interval set in fractions of a second: a number of seconds, not a clock time.

A setting told in seconds is read as a time (shown m:ss, stepped in whole seconds). One the
manual steps by part of a second ("from 2 to 10 seconds in half-second steps", "0.1 s a press")
and that stays under a minute is a plain number of seconds: the display prints "3.5 s", and a
time's whole-second grid would lose every half step.
"""

from __future__ import annotations

from collections.abc import Sequence

from apbot.read.shapes import Range

_MINUTE = 60.0


def part_seconds(step: tuple[float, str] | None, ranges: Sequence[Range]) -> bool:
    """Whether a range in seconds steps by a fraction of a second and stays under a minute."""
    if not step or step[1] != "s" or not 0 < step[0] < 1 or not ranges:
        return False
    return all(r.unit in ("s", "") and r.high < _MINUTE for r in ranges)
