"""Readings of a numeric scale with codes: a setting whose values are numbers and a code or two
(a hob's 0..9 and P past 9, a dehumidifier's CO below 30 %, a fan's 1..5 and AUTO).

The reader keeps such a setting as a list of words, and a list accepts any text after the
setting's label as a value the belief lacks (``outside``). For a scale that is too loose: a
display that prints another screen after the same label (``FRONT TIMER 5 min`` beside ``FRONT
5``) would be read as the level ``TIMER 5 min``, and the closed loop would chase it. A plain
numeric scale reads only numbers there; a scale with codes reads only text of its own values'
shape — one word (``12``, ``P``, ``HI``) or a number with a short unit (``45 %``).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

_NUMBER = re.compile(r"[-+]?\d+(?:[.,]\d+)?")
_SHAPE = re.compile(r"\S+|[-+]?\d+(?:[.,]\d+)?\s*[^\s\d]{1,3}")


def is_scale_with_codes(values: Sequence[Any]) -> bool:
    """Whether a list of values is mostly a numeric scale (three numbers or more, at least
    half of the values) whose other values are single words."""
    texts = [str(v) for v in values]
    numbers = sum(1 for t in texts if _NUMBER.fullmatch(t))
    if numbers < 3 or numbers * 2 < len(texts):
        return False
    return all(" " not in t.strip() for t in texts)


def off_scale(values: Sequence[Any], text: str) -> bool:
    """Whether ``text``, read where such a scale's value is printed, cannot be one of its
    values (several words: another screen after the same label)."""
    return is_scale_with_codes(values) and not _SHAPE.fullmatch(text.strip())
