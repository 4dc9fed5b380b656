"""Turns said in words are angles: "upside down" is 180°, "a quarter turn clockwise" 90°,
"a quarter turn anticlockwise" 270°, "a half turn" 180°.

A design, a display or an image is rotated in right angles on many panels (ROTATION 0 / 90 /
180 / 270 °); people name the turn rather than the degrees. The phrase is written as the
rotating setting's name and its angle first, only on a model with exactly one setting counted
in degrees that takes 90, 180 and 270 and is named for turning.
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.read.goal_values import unit_text
from apbot.read.goal_view import Model

_AGAINST = r"(?:anti|counter)[- ]?clockwise"
_TURNS = (
    (re.compile(rf"\b(?:a\s+)?quarter[- ]turn\s+(?:to\s+the\s+left|{_AGAINST})", re.I), 270),
    (re.compile(r"\b(?:a\s+)?three[- ]quarters?[- ]turn(?:\s+clockwise)?", re.I), 270),
    (re.compile(r"\b(?:a\s+)?quarter[- ]turn(?:\s+(?:to\s+the\s+right|clockwise))?", re.I), 90),
    (re.compile(r"\bupside[- ]down\b|\b(?:a\s+)?half[- ]turn\b", re.I), 180),
)
_TURNING = re.compile(r"rotat|turn|angle|orient", re.I)


def _rotation(view: Model) -> str | None:
    found = []
    for name, info in view.infos.items():
        var = info.var
        if not isinstance(var, NumericVariable) or unit_text(var).strip() not in ("°", "deg"):
            continue
        if not _TURNING.search(f"{name} {var.label or ''}"):
            continue
        values = {float(v) for v in all_values(var)}
        if {90.0, 180.0, 270.0} <= values:
            found.append(name)
    return found[0] if len(found) == 1 else None


def said_turns(view: Model, instruction: str) -> str:
    """ "upside down" as "rotation 180" on a model with one ROTATION of right angles."""
    if not any(pattern.search(instruction) for pattern, _ in _TURNS):
        return instruction
    name = _rotation(view)
    if name is None:
        return instruction
    for pattern, degrees in _TURNS:
        instruction = pattern.sub(f"{name.replace('_', ' ')} {degrees}", instruction)
    return instruction
