"""Fields of a walk that the manual values elsewhere: a setting already read (the temperature a
programme chart gave), or one whose values only a chart's column gives.

"Step 2 Touch SET. The temperature flashes, e.g. 200°C. Step 3 Set the temperature with ▲ / ▼.
Step 4 Touch SET. The pressing time flashes, e.g. t 30 s. Step 5 Set the time with ▲ / ▼." The
steps say which setting flashes but give no values: those are in the chart ("Programme |
Temperature | Pressing time", a range per programme). The first field is the temperature the
chart was read for; the second is named by the words that flash and valued by the column
headed by them (the chart's cases are read for it afterwards, as for any setting).
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_tables import _tables
from apbot.read.shapes import Evidence
from apbot.read.value_steps import find_step
from apbot.read.values import Range, find_ranges
from apbot.read.walk_fields import after_key

# the setting that flashes when the walk's key opens it: "The pressing time flashes, e.g. …"
_FLASHES_RE = re.compile(
    r"^(?:the\s+)?((?:[a-z]+\s){0,2}?[a-z]+)\s+(?:flashes|blinks|is\s+flashing)\b", re.I
)


def flashing_name(shown: str) -> str:
    """The name of the setting a step says flashes, else ""."""
    m = _FLASHES_RE.match(after_key(shown))
    return "_".join(m.group(1).lower().split()) if m else ""


def known_field(b: Builder, shown: str, at: int) -> dict[str, Any] | None:
    """A walk field the step names only by what flashes: a setting read already, else one a
    chart's column of ranges headed by the same words values."""
    name = flashing_name(shown)
    if not name:
        return None
    if name in b.variables and b.variables[name].get("type") in ("numeric", "time"):
        return {"name": name, "known": True, "label": b.variables[name].get("label", "")}
    ranges = _column_ranges(b, name)
    if not ranges:
        return None
    low, high = min(r.low for r in ranges), max(r.high for r in ranges)
    steps = [r.step for r in ranges if r.step]
    step = (min(steps), ranges[0].unit) if steps else None
    ev = Evidence(ranges=[Range(low, high, ranges[0].unit)], range_at=at, step=step, step_at=at)
    return {"name": name, "evidence": ev, "charted": True}


def _column_ranges(b: Builder, name: str) -> list[Range]:
    """The ranges of a chart's column headed by the field's words ("Pressing time"), in one
    unit, each with its step where the cell gives one ("10 - 60 s, 5 s steps")."""
    wanted = name.split("_")
    for header, rows in _tables(b.manual.units):
        for column, head in enumerate(header):
            if re.findall(r"[a-z]+", head.lower()) != wanted:
                continue
            out: list[Range] = []
            for row in rows:
                cell = row.cells[column] if column < len(row.cells) else ""
                found = find_ranges(cell)
                step = find_step(cell)
                out += [Range(r.low, r.high, r.unit, step[0] if step else None) for r in found]
            if out and len({r.unit for r in out}) == 1 and out[0].unit:
                return out
    return []


def use_known(b: Builder, name: str, pair: set[str]) -> str:
    """The walk sets a setting read already: drop the reading of the pair alone setting it
    (the pair works inside the walk), keep the setting and its cases."""
    for fname, steps in list(b.features.items()):
        if (
            len(steps) == 1
            and steps[0].get("variable") == name
            and set(steps[0].get("actions", [])) <= pair
        ):
            del b.features[fname]
    return name
