"""Keys that move several settings to stored values at once, read from the chart of them.

A manual charts one-touch keys as rows of a table whose other columns are headed by settings
the appliance already has ("| Key | Head | Foot |" over "| FLAT | 0° | 0° |", "| TV | 45° |
15° |"; a lamp's "| Scene | Brightness | Colour |" over "| READ | 80 % | 4000 K |"). Each such
key sets those settings to the values in its row (a cell saying no value, "unchanged", leaves
that setting alone); it is no setting of its own, whatever an earlier stage made of its row's
figures.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_cells import _figure
from apbot.read.cases_tables import _tables
from apbot.read.held_guesses import _drop_unused
from apbot.read.labels import words


def _setting_of(b: Builder, head: str, skip: set[str]) -> str | None:
    """The numeric setting a column head names by its whole name ("Head", "Foot angle")."""
    said = set(words(head))
    for name, spec in b.variables.items():
        if name in skip or spec.get("type") != "numeric" or spec.get("depends_on"):
            continue
        if set(words(name.replace("_", " "))) <= said:
            return name
    return None


def _within(spec: dict[str, Any], value: float) -> bool:
    return any(lo <= value <= hi for lo, hi, _ in spec.get("ranges") or [])


def read_preset_keys(b: Builder) -> None:
    """Make each charted one-touch key set the settings its row gives."""
    press_of = {
        b.labels[i.controls[0]].text.strip().upper(): i.name
        for i in b.infos
        if i.skill == "press" and len(i.controls) == 1 and i.controls[0] in b.labels
    }
    for header, rows in _tables(b.manual.units):
        keyed = [r for r in rows if r.cells and r.cells[0].strip(" *").upper() in press_of]
        if len(keyed) < 2 or len(header) < 2:
            continue
        own = {v for r in keyed for f in b.features.values() for s in f
               if press_of[r.cells[0].strip(" *").upper()] in s.get("actions", [])
               for v in [s.get("variable")] if v}  # fmt: skip
        columns = {c: s for c in range(1, len(header)) if (s := _setting_of(b, header[c], own))}
        if not columns:
            continue
        for row in keyed:
            sets: dict[str, Any] = {}
            for c, var in columns.items():
                value = _figure(re.sub(r"°", " °", row.cells[c])) if c < len(row.cells) else None
                if value is not None and _within(b.variables[var], value):
                    sets[var] = value
            if not sets:
                continue
            action = press_of[row.cells[0].strip(" *").upper()]
            old = [n for n, f in b.features.items() if any(action in s["actions"] for s in f)]
            if any(len(b.features[n]) > 1 for n in old):
                continue  # the key opens a walk: not a one-touch key
            made = [str(s["variable"]) for n in old for s in b.features[n] if s.get("variable")]
            for n in old:
                del b.features[n]
            for made_var in made:
                _drop_unused(b, made_var)
            first, *rest = sets
            step: dict[str, Any] = {
                "actions": [action],
                "variable": first,
                "effect": {"to": sets[first]},
            }
            if rest:
                step["set"] = {v: sets[v] for v in rest}
            b.feature(action.removeprefix("press_"), [step])
            b.note(
                f"features.{action.removeprefix('press_')}",
                "sets " + ", ".join(f"{k} {v}" for k, v in sets.items()),
                b.manual.units.index(row),
            )
