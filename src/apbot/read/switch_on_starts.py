"""Where a setting starts, said of switching on anywhere in the manual: "When switched on the
fan runs at speed 3", "After power-up the mister starts at level 2". A sentence about switching
on that names the setting right before a figure ("speed 3") gives that setting's start, even
far from the setting's key: manuals say what the appliance does at switch-on once, in its
operating section, not beside each key.
"""

from __future__ import annotations

import re

from apbot.read.labels import CONTROL_NOUNS
from apbot.read.shapes import Evidence
from apbot.read.text import Unit
from apbot.read.values import NUM, number

# "when switched on", "once it is turned on", "after switching on", "at power-up", "on start-up"
_SWITCH_ON = (
    r"\b(?:(?:when|once|after|as soon as)\s+(?:\w+\s+){0,3}?"
    r"(?:switch(?:ed|ing)?|turn(?:ed|ing)?|power(?:ed|ing)?)\s+on"
    r"|(?:at|on|after)\s+(?:power[- ]?up|switch[- ]?on|start[- ]?up))\b"
)
# "The humidifier starts at mist level II": the appliance (not a key) starting at a named value
_STARTS_AT = r"\b(?:starts?|begins?)\s+(?:at|on|in|with)\s+(?:the\s+)?"


def switch_on_start(units: list[Unit], names: set[str]) -> tuple[float, int] | None:
    """The figure a switch-on sentence gives right after one of the setting's ``names``
    ("runs at speed 3" for ``speed``), and the unit it is said in."""
    if not names:
        return None
    named = "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))
    pattern = re.compile(
        rf"{_SWITCH_ON}[^.;]*?\b(?:{named})\s+(?:level\s+|setting\s+)?({NUM})(?![\w:.,]\d)",
        re.IGNORECASE,
    )
    for i, unit in enumerate(units):
        if unit.cells:
            continue
        m = pattern.search(unit.text)
        if m and (value := number(m.group(1))) is not None:
            return value, i
    return None


def starts_at_value(
    units: list[Unit], names: set[str], values: list[str]
) -> tuple[str, int] | None:
    """The value of ``values`` a sentence gives right after one of the setting's ``names``,
    of switching on or of the appliance starting ("starts at mist level II"), and its unit."""
    if not names or not values:
        return None
    named = "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))
    said = "|".join(re.escape(v) for v in sorted(values, key=len, reverse=True))
    pattern = re.compile(
        rf"(?:{_SWITCH_ON}[^.;]*?|{_STARTS_AT})\b(?:{named})\s+(?:level\s+|setting\s+|mode\s+)?"
        rf"({said})(?!\w)",
        re.IGNORECASE,
    )
    for i, unit in enumerate(units):
        m = None if unit.cells else pattern.search(unit.text)
        if m:
            return next(v for v in values if v.lower() == m.group(1).lower()), i
    return None


def start_at_switch_on(units: list[Unit], ev: Evidence, own_words: set[str]) -> None:
    """A start said once, of switching on, by the setting's name and a figure
    (:func:`switch_on_start`): one of the values read (``ev``'s), in their unit."""
    names = {w for w in own_words if not re.fullmatch(CONTROL_NOUNS, w)}
    found = switch_on_start(units, names)
    if found is None:
        if ev.values and ev.initial is None and (told := starts_at_value(units, names, ev.values)):
            ev.initial, ev.initial_at = told
        return
    value, at = found
    if ev.ranges:
        if min(p.low for p in ev.ranges) <= value <= max(p.high for p in ev.ranges):
            ev.initial, ev.initial_at = (value, ev.ranges[0].unit), at
        return
    for v in ev.values or []:
        if number(re.sub(r"[^\d.,]", "", v) or "x") == value:
            ev.initial, ev.initial_at = v, at
            return
