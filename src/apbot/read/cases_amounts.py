"""A programme table's column read as an amount: a preset's starting value per programme, a
column headed with its unit ("Wash (min)"), a column of ranges that makes a discrete setting
(or whole hours) a number, and a toggle that steps on once a setting has more than two values.
Apart from cases.py, which finds the tables and matches their columns to settings, because
these rewrite one setting's spec once that match is made."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import parse_hms
from apbot.read.build import Builder
from apbot.read.cases_cells import chain_values, time_list
from apbot.read.text import Unit
from apbot.read.values import Range, find_ranges, unit_name


def _presets(b: Builder, parent: str, name: str, cases: dict[str, Any], row: Unit) -> bool:
    """Keys that each load one amount ("FRIES — 200 °C", "BOIL — 100 °C") give the amount a
    starting value per preset, not a one-value domain: the +/− keys still adjust it over its
    whole range (a preset the table leaves out keeps the range, from its start). Only for a
    table of single values."""
    spec = b.variables[name]
    if spec.get("type") not in ("numeric", "time") or not spec.get("ranges"):
        return False
    if not set(cases) <= set(b.variables[parent].get("values", [])):
        return False
    single: dict[str, Any] = {}
    for value, case in cases.items():
        ranges = case.get("ranges") or []
        if len(ranges) != 1 or ranges[0][0] != ranges[0][1]:
            return False
        single[value] = ranges[0][0]
    ranges = [list(r) for r in spec["ranges"]]
    if spec["type"] == "numeric":
        lo, hi, step = ranges[0][0], ranges[-1][1], ranges[0][2]
        values = list(single.values())
        if (
            len(ranges) > 1
            or any((v - lo) % step for v in values)
            or min(values) < lo
            or max(values) > hi
        ):
            low, high = min([lo, *values]), max([hi, *values])
            step = _gcd_step(step, single, low)
            ranges = [[low, low + int((high - low) / step) * step, step]]
    else:
        secs = [parse_hms(str(v)) for v in single.values()]
        lo_t, hi_t = parse_hms(ranges[0][0]), parse_hms(ranges[-1][1])
        if (
            min(secs) < lo_t
            or max(secs) > hi_t
            or any((t - lo_t) % int(ranges[0][2]) for t in secs)
        ):
            return False
    for key in ("ranges", "initial", "values"):
        spec.pop(key, None)
    spec["depends_on"] = parent
    spec["cases"] = {
        v: {"ranges": ranges, **({"initial": single[v]} if v in single else {})}
        for v in b.variables[parent]["values"]
    }
    b.note(
        f"variables.{name}.cases",
        f"each {parent} loads its own starting value: "
        + ", ".join(f"{k} {v}" for k, v in single.items()),
        b.manual.units.index(row),
    )
    return True


def _gcd_step(step: float, values: dict[str, Any], low: float) -> float:
    """The largest step from ``low`` that reaches every preset (1 when they are whole)."""
    from math import gcd

    if all(float(v).is_integer() for v in values.values()) and float(step).is_integer():
        g = int(step)
        for v in values.values():
            g = gcd(g, int(v - low))
        return g or 1
    return 1 if all(float(v).is_integer() for v in values.values()) else 0.5


HEADER_UNIT_RE = re.compile(  # "(s)" glued to a word is a plural ending ("Option(s)")
    r"\(\s*(min|mins|minutes|h|hrs|hours|sec|°c|°f|%|rpm|w|g|kg|ml|l)\s*\)"
    r"|(?<![A-Za-z])\(\s*(s)\s*\)",
    re.I,
)


def _header_unit(spec: dict[str, Any], header: str) -> None:
    """A column headed with its unit ("Wash (min)", "Temp (°C)") gives an amount read without
    one that unit, so that a goal's "24-minute wash" finds it."""
    if spec.get("type") != "numeric" or spec.get("unit"):
        return
    m = HEADER_UNIT_RE.search(header)
    if m:
        spec["unit"] = unit_name(m.group(1) or m.group(2))


def _ranges_column(rows: list[Unit], column: int) -> bool:
    return sum(bool(column < len(r.cells) and find_ranges(r.cells[column])) for r in rows) >= 2


def _finer_times(spec: dict[str, Any], rows: list[Unit], column: int) -> bool:
    """Whether a setting read as whole hours (a numeric "h") has a column of times in a finer
    unit ("1 – 60 min", "1 min – 2 h"): it is a time, set in minutes."""
    if spec.get("type") != "numeric" or spec.get("unit") != "h":
        return False
    found = [
        f[0] for r in rows if column < len(r.cells) and (f := _ranges_or_list(r.cells[column]))
    ]
    return len(found) >= 2 and any(r.unit in ("min", "s") for r in found)


def _ranges_or_list(cell: str) -> list[Range]:
    """The ranges a cell gives, or the span of the times it lists ("20 / 30 / 40 min")."""
    listed = time_list(cell)
    if listed and not find_ranges(cell):
        return [Range(listed[0][0] // 60, listed[0][-1] // 60, "min")]
    return find_ranges(cell)


def _as_number(b: Builder, name: str, spec: dict[str, Any], rows: list[Unit], column: int) -> None:
    """Turn a read-as-discrete setting (or whole hours) into the amount the table's ranges say
    it is, read from the column's first range in the finest unit it uses."""
    from apbot.read.shapes import Evidence

    cells = [r.cells[column] for r in rows if column < len(r.cells)]
    found = [_ranges_or_list(c) for c in cells]
    chains = [chained[0] for c in cells if (chained := chain_values(c))]
    first = next(f[0] for f in found if f)
    first = next((f[0] for f in found if f and f[0].unit in ("min", "s")), first)
    if chains:  # "0-1-3-[5]-7-9": the values listed, not a range "0-1"
        first = Range(min(c[0] for c in chains), max(c[-1] for c in chains), first.unit)
    label = spec.get("label", name.upper())
    # a key that only steps on ("each press shows the next spin time") comes round again
    alone = any(
        st.get("variable") == name and st.get("effect") == "next" and len(st["actions"]) == 1
        for steps in b.features.values()
        for st in steps
    )
    del b.variables[name]
    new = b.add_number(name, label, Evidence(ranges=[first]), cyclic=alone)
    if new != name:  # keep the name the features use
        b.variables[name] = b.variables.pop(new)
    spec.clear()
    spec.update(b.variables[name])
    b.variables[name] = spec
    _no_toggle(b, name, {"x": {"values": []}})


def _no_toggle(b: Builder, name: str, cases: dict[str, Any]) -> None:
    """A toggle on a setting that now has more than two values in some programme steps on."""
    if all(len(c.get("values", [])) == 2 for c in cases.values()):
        return
    for steps in b.features.values():
        for step in steps:
            if step.get("variable") != name:
                continue
            effect = step.get("effect")
            if effect == "toggle":
                step["effect"] = "next"
            elif isinstance(effect, dict):
                step["effect"] = {a: "next" if e == "toggle" else e for a, e in effect.items()}
