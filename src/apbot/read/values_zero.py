"""A setting whose zero means "none": "(0 h = no timer)", "**0** means no timer", "DELAY 0 h:
no delay", "or 0 if no timer is set", "after 24 h it goes back to 0 h, which means no timer".

Manuals give a timer's or a delay's range from its first real value ("1 - 24 hours") and tell
the zero apart, as the setting switched off; the panel still steps through it. So a range read
above zero gains zero when a sentence naming the setting says its zero is none."""

from __future__ import annotations

import re

from apbot.read.labels import words
from apbot.read.values import UNIT, Range, is_time_unit, unit_name

_NONE = r"(?:no|none|off|cancel(?:led|s)?)\b"
_ZERO_NONE_RE = re.compile(  # "0 h = no timer", "**0** means no timer", "0 if no timer is set"
    rf"(?<![\w.,:])0(?!\.\d)\s*({UNIT})?\**\s*(?:=|:|means|is|if)\s*\(?{_NONE}"
    rf"|\bback\s+to\s+0\s*({UNIT})?\**\s*(?:\(|,)?\s*(?:which\s+means\s+|meaning\s+|i\.e\.\s+)?{_NONE}",
    re.IGNORECASE,
)


def zero_told(texts: list[str], names: set[str], unit: str) -> int | None:
    """The index of the first text that says the setting's zero, in ``unit`` or with no unit,
    is none, naming the setting (one of ``names``) in the words just before or in the saying
    ("TIMER 0 h = off", "0 means no timer"); else None."""
    for i, text in enumerate(texts):
        for m in _ZERO_NONE_RE.finditer(text):
            said = m.group(1) or m.group(2)
            after = re.match(r"\s*(\w+)", text[m.end() :])
            near = words(text[max(0, m.start() - 30) : m.start()]) + words(m.group(0))
            near += [after.group(1).lower()] if after else []
            if names & set(near) and (said is None or _same_kind(unit_name(said), unit)):
                return i  # ("d 0 h = no delay" near the drying TIME says nothing of the time)
    return None


def from_zero(ranges: list[Range], step: float | None) -> list[Range]:
    """The ranges with zero in front: the first range starts at zero when its step (or the
    setting's ``step``, in its unit) reaches its low end in one press, else zero is a piece of
    its own, one press below."""
    first = ranges[0]
    each = first.step or step
    if each and abs(each - first.low) < 1e-9:
        return [Range(0, first.high, first.unit, each), *ranges[1:]]
    return [Range(0, first.low, first.unit, first.low), *ranges]


def _same_kind(said: str, unit: str) -> bool:
    return said == unit or (is_time_unit(said) and (is_time_unit(unit) or unit in ("s", "")))
