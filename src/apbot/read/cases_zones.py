"""Zones that work alike: a setting of zone 2 depends on zone 2's programme as zone 1's does.

A dual-zone appliance (two baskets, two hob zones) prints one programme table for both zones;
the table makes the first zone's setting depend on the first zone's programme (``temperature_1``
on ``menu1``) and leaves its twin of the second zone (``temperature_2``) one flat range, which
neither resets with ``menu2`` nor knows the programmes' limits. When both zones' programme
variables list the same programmes, the twin takes the same cases on its own zone's programme.
"""

from __future__ import annotations

import copy
import re
from typing import Any

from apbot.read.build import Builder

_NUMBERED_RE = re.compile(r"^(?P<base>.*?[a-z])_?(?P<n>\d+)$")


def _split(name: str) -> tuple[str, str] | None:
    m = _NUMBERED_RE.match(name)
    return (m.group("base"), m.group("n")) if m else None


def zone_twins(b: Builder) -> None:
    """Give each numbered setting's twin of another zone the same programme cases, on that
    zone's programme."""
    for name, spec in list(b.variables.items()):
        parent = spec.get("depends_on")
        own, mother = _split(name), _split(parent) if parent else None
        if not parent or own is None or mother is None or own[1] != mother[1]:
            continue
        for twin, tspec in b.variables.items():
            other = _split(twin)
            if other is None or other[0] != own[0] or other[1] == own[1]:
                continue
            if tspec.get("depends_on") or not _alike(spec, tspec):
                continue
            zone_parent = next((p for p in b.variables if _split(p) == (mother[0], other[1])), None)
            if zone_parent is None:
                continue
            if b.variables[zone_parent].get("values") != b.variables[parent].get("values"):
                continue
            for key in ("values", "ranges", "initial"):
                tspec.pop(key, None)
            tspec["depends_on"] = zone_parent
            tspec["cases"] = copy.deepcopy(spec["cases"])
            tspec["type"] = spec["type"]
            if spec["type"] == "time":
                tspec.pop("unit", None)
            for key in ("unit", "format"):
                if key in spec:
                    tspec[key] = spec[key]
            b.note(f"variables.{twin}.cases", f"as {name}'s, on {zone_parent} (zones alike)")


def _alike(spec: dict[str, Any], twin: dict[str, Any]) -> bool:
    """Whether the twin is the same kind of setting: the same type, or whole hours beside a
    time (the table turned zone 1's hours into a time set in minutes)."""
    if twin.get("type") == spec.get("type"):
        return True
    return spec.get("type") == "time" and twin.get("type") == "numeric" and twin.get("unit") == "h"
