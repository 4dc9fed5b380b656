"""A specifications row of step sizes: "| Wheel increments | 5 / 10 / 25 µL |".

A data table often gives how far one click or press moves a setting ("Increments", "Step
size", "Resolution", "Adjustment steps") beside its range. The figures in such a row are the
sizes of the steps, never values to choose: read as a list, they would give the key or dial a
setting of three values (5, 10, 25 µL) that the appliance has nowhere.
"""

from __future__ import annotations

import re

from apbot.read.evidence_whose import lead_cell
from apbot.read.text import Unit

_STEP_ROW = re.compile(
    r"\b(?:increments?|step\s+sizes?|steps?\s+of\s+adjustment|adjustment\s+steps?|resolution"
    r"|graduations?)\s*$",
    re.I,
)


def step_size_row(unit: Unit) -> bool:
    """The unit is a table row named for step sizes (its lead cell ends with "increments",
    "step size", "resolution" …)."""
    return bool(unit.cells) and bool(_STEP_ROW.search(lead_cell(unit.cells).strip(" *:")))
