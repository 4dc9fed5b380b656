"""A short press of one key that opens a walk through several fields, each set with the
stepping pair, the same key moving on to the next ("1. Touch SET. The display shows P1. 2. Choose
the memory with ▲ or ▼. 3. Touch SET. The display shows SEX M. 4. Choose the sex with ▲ or ▼ …").

The held walks (``held_walks``) are opened by a hold; most manuals open a settings walk with a
plain press of SET, MENU or CLOCK. Read key by key, that press was a guessed switch and the
fields a guessed amount or nothing. The fields are named by the manual's field order when it
prints one ("USER (P) -> SEX -> AGE -> HEIGHT -> stored"), else by what the display shows.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases import apply_cases
from apbot.read.held_walks import stepped_walk
from apbot.read.walk_apply import apply_walk
from apbot.read.walk_keys import moves_on, pair_of, stepping_pairs
from apbot.read.walk_order import order_names
from apbot.read.walk_steps import walk_steps


def read_pressed_walks(b: Builder) -> None:
    """Add the walks a key's short press opens in numbered steps (two fields at least)."""
    units = b.manual.units
    pairs = stepping_pairs(b)
    if not pairs:
        return
    paired = {a for up, down in pairs for a in up + down}
    for info in list(b.infos):
        if info.skill != "press" or info.name in paired or len(info.controls) != 1:
            continue
        if info.controls[0] not in b.labels or _walked(b, info.name):
            continue
        label = b.labels[info.controls[0]].text
        for i, unit in enumerate(units):
            if unit.step is None or not moves_on(unit.text, label):
                continue
            groups = walk_steps(units, i)
            if len(groups) < 4 or pair_of(b, pairs, groups[1][1]) is None:
                continue
            walk = stepped_walk(b, groups, label, pairs, i)
            if walk is None or "clock" in walk:
                continue
            _name_by_order(b, walk, i)
            apply_walk(b, info.name, info.name, walk, named=False)
            if any(f.get("charted") for f in walk["fields"]):
                apply_cases(b)  # a field valued by a chart's column: its cases per programme
            break


def _walked(b: Builder, press: str) -> bool:
    """The press already moves through a walk read before (a held walk's "press")."""
    return any(
        len(steps) > 2 and any(s.get("actions") == [press] for s in steps[1:])
        for steps in b.features.values()
    )


def _name_by_order(b: Builder, walk: dict[str, Any], at: int) -> None:
    """Name the walk's fields by the field order its section prints, when the order has as many
    fields as the walk read (or more: the walk may stop before the last)."""
    units = b.manual.units
    lines = [u.text for u in units[max(0, at - 15) : at + 25]]  # (the order may head the section)
    fields = walk["fields"]
    for names in order_names(lines):
        if len(names) < len(fields):
            continue
        if len(names) == len(fields) or _agrees(names, fields):
            for field, name in zip(fields, names, strict=False):
                field["name"] = name
            return


def _agrees(names: list[str], fields: list[dict[str, Any]]) -> bool:
    """The order's names and the fields' own names share at least one field in place."""
    return any(
        re.sub(r"s$", "", n) in f["name"].split("_") for n, f in zip(names, fields, strict=False)
    )
