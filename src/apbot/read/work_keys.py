"""A key that starts and stops the work, though not named START: "PLAY – starts or stops
cooking", "RUN – starts or stops watering". Its own legend line says it starts or stops the
appliance's work (an -ing noun of work, the programme, the cycle, the operation, a clock's game
or session: "▶/❚❚  start or pause the game"); a key that
"starts or stops oscillation", "the timer" or "the moving louvre" runs a feature or a part,
not the appliance: the work noun must end the clause.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_holdcell import _own_rows

_STARTS_STOPS_RE = re.compile(
    r"\b(?:starts?|begins?)\s+(?:or|and|/)\s+(?:stops?|pauses?|ends?|cancels?)\s+(?:the\s+)?"
    r"(?:[a-z]+ing|program(?:me)?|cycle|process|operation|appliance|machine|game|session)"
    r"(?=\s*(?:$|[.;,:)|]|\s(?:and|or|now|at|when|immediately)\b))",  # ("the moving louvre",
    # "the cooking timer": an -ing word before a noun names a part or a feature)
    re.IGNORECASE,
)


def starts_and_stops(b: Builder, info: ActionInfo) -> bool:
    """Whether a pressed key's own line says it starts or stops the appliance's work."""
    if info.skill != "press" or len(info.controls) != 1 or info.controls[0] not in b.labels:
        return False
    units = b.manual.units
    label = b.labels[info.controls[0]]
    # (its first mentions, or its own legend row further on: "▶/❚❚  start or pause the game"
    # after the drawing and the display legend printed the sign three times)
    said = [*label.mentions[:3], *_own_rows(b, info)]
    if any(_STARTS_STOPS_RE.search(units[i].text) for i in said):
        return True
    return any(_own_work(units[i].text, label.text) for i in said)


_OWN_WORK_RE = re.compile(
    r"\b(?:starts?|begins?)\s+(?:or|and|/)\s+(?:stops?|ends?|cancels?)\s+(?:an?|the)\s+"
    r"([a-z]{4,})(?=\s*(?:$|[.;,:()|]))",
    re.IGNORECASE,
)


def _own_work(text: str, label: str) -> bool:
    """A key named by a verb whose line says it starts or stops the noun of that verb
    ("EXPOSE  start / stop an exposure", "BREW – starts or stops a brew"): the key runs the
    appliance's one job. The noun shares the label's first five letters (four for a label of
    four), so "starts or stops the timer" on a key named otherwise is not it."""
    name = label.strip().lower()
    if not re.fullmatch(r"[a-z]{4,}", name):
        return False
    m = _OWN_WORK_RE.search(text)
    return m is not None and m.group(1).lower()[: min(5, len(name))] == name[:5]
