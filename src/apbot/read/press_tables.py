"""A table of key presses: "| TIMER once | 10 minutes |", "| TIMER twice / three times | 20 / 30
minutes |", "| TIMER four times | timer off |".

Quick-reference cards tell a one-key setting by how often the key is pressed, one row per count,
rather than as a list. Read key by key the rows say nothing a list reader takes, and the key was
guessed a toggle or an amount of guessed range. The rows in count order give the values the key
steps through; a count after the last comes back round, so the value that ends the cycle ("off")
is where it starts. Only amounts of one unit and an "off" are read: rows that describe effects
("+1 °C", "bubbles on") are left to the other rules.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.roles_lists import list_evidence
from apbot.read.shapes import Evidence
from apbot.read.values import NUM, UNIT, unit_name

_COUNTS = {"once": 1, "twice": 2, "three times": 3, "four times": 4, "five times": 5,
           "six times": 6}  # fmt: skip
_COUNT_RE = re.compile(r"^(?:once|twice|(?:three|four|five|six) times|(\d)\s*(?:times|×|x))$")
_AMOUNT_RE = re.compile(rf"^({NUM})\s*({UNIT})?$", re.IGNORECASE)


def _count(text: str) -> int | None:
    text = text.strip().lower()
    m = _COUNT_RE.match(text)
    if m is None:
        return None
    return int(m.group(1)) if m.group(1) else _COUNTS[text]


def _rows(b: Builder, label: str) -> dict[int, tuple[str, int]]:
    """{press count: (what that count gives, unit index)} of the key printed ``label``."""
    out: dict[int, tuple[str, int]] = {}
    lead = re.compile(rf"^{re.escape(label)}\s+(.+)$", re.IGNORECASE)
    for i, unit in enumerate(b.manual.units):
        if not unit.cells or len(unit.cells) < 2 or not (m := lead.match(unit.cells[0].strip())):
            continue
        counts = [_count(c) for c in m.group(1).split("/")]
        results = [r.strip() for r in unit.cells[1].split("/")]
        if None in counts or len(results) != len(counts):
            continue
        for n, result in zip(counts, results, strict=True):
            out[n or 0] = (result, i)
    return out


def _amounts(results: list[str]) -> list[str] | None:
    """The amounts the results give, in one unit ("20", "30 minutes": both minutes), "off"
    for a result that switches the setting off; None when a result is something else."""
    unit = ""
    for r in results:
        m = _AMOUNT_RE.match(re.sub(r"\s*\(.*\)$", "", r))
        if m and m.group(2):
            unit = unit or unit_name(m.group(2))
    out: list[str] = []
    for r in results:
        plain = re.sub(r"\s*\(.*\)$", "", r)
        m = _AMOUNT_RE.match(plain)
        if m and (not m.group(2) or unit_name(m.group(2)) == unit):
            out.append(f"{m.group(1)} {unit}".strip())
        elif re.search(r"\boff\b", plain, re.IGNORECASE) and len(plain.split()) <= 3:
            out.append("off")
        else:
            return None
    return out if unit and sum(v != "off" for v in out) >= 2 else None


def read_press_tables(b: Builder) -> None:
    """Give a key guessed a toggle or a guessed range the values its press-count rows list."""
    for steps in list(b.features.values()):
        var = steps[0].get("variable")
        if len(steps) != 1 or len(steps[0]["actions"]) != 1 or var in (None, "power", "running"):
            continue
        guessed = any(n.guess and n.subject in (f"variables.{var}", f"features.{var}")
                      for n in b.notes)  # fmt: skip
        key = next((i for i in b.infos if i.name == steps[0]["actions"][0]), None)
        if not guessed or key is None or len(key.controls) != 1 or key.controls[0] not in b.labels:
            continue
        rows = _rows(b, b.labels[key.controls[0]].text)
        if len(rows) < 3 or sorted(rows) != list(range(1, len(rows) + 1)):
            continue
        values = _amounts([rows[n][0] for n in sorted(rows)])
        if values is None:
            continue
        if values[-1] == "off":  # the count that ends the cycle switches it off: it starts so
            unit = next(v for v in values if v != "off").split()[-1]
            values = [f"0 {unit}", *values[:-1]]
        if "off" in values:
            continue
        at = rows[1][1]
        spec_name = _renumbered(b, var, values, at)
        steps[0]["variable"] = spec_name
        steps[0]["effect"] = "next"
        b.note(f"variables.{spec_name}", "the key's press-count rows: " + ", ".join(values), at)


def _renumbered(b: Builder, var: str, values: list[str], at: int) -> str:
    """Replace ``var`` by a cyclic amount over ``values`` (the first, zero, its start)."""
    label = str(b.variables[var].get("label") or var.upper())
    del b.variables[var]
    ev = list_evidence(Evidence(values=values, values_at=at))
    name = b.add_number(var, label, ev, cyclic=True)
    spec: dict[str, Any] = b.variables[name]
    first = spec.get("ranges", [[None]])[0][0]
    if values[0].startswith("0") and first is not None:
        spec["initial"] = first
    return name
