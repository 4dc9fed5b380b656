"""Whose a key's list is when the key is both touched and held.

The manual's evidence is gathered per key, but a key with two jobs says which job a list
belongs to: "Hold LIGHT for 3 seconds to change the colour. Each hold selects the next colour:
WHT, BLU, …" gives the hold its colours (a touch switches the light on and off), and the key
table's row "| MODE | Next heating mode ST → EC → SL | 3 s: filter cycle programming |" gives
the modes to the touch (holding MODE programmes something else). A list read where only the
other way of working the key is said is not this action's.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_holdcell import HOLD_CELL, hold_cells
from apbot.read.shapes import comes_round

# a short press said as such: "Touch LIGHT", "press MODE briefly"
_PRESSING = r"(?:press|touch|push|tap)(?:es|ed|ing)?"


def _twin(b: Builder, key: ActionInfo) -> bool:
    """The same key is also worked the other way (a hold beside the press, or the reverse)."""
    other = "hold" if key.skill == "press" else "press"
    return any(i.skill == other and i.controls == key.controls for i in b.infos)


def _in_cells(values: list[str], cells: list[str]) -> bool:
    """Every value is written in one of these cells."""
    text = " ".join(cells).lower()
    return bool(cells) and all(v.lower() in text for v in values)


def others_list(b: Builder, key: ActionInfo, values: list[str], at: int | None) -> bool:
    """Whether the list ``values`` read at unit ``at`` belongs to the other way of working this
    key: for a press, a sentence (or the sentence before it in its paragraph) that holds the
    key by name and never presses it, or a key-table row with the list only in its "hold"
    cells; for a hold, a key-table row whose list stands outside its "hold" cells."""
    if at is None or not values or key.skill not in ("press", "hold") or len(key.controls) != 1:
        return False
    if key.controls[0] not in b.labels or not _twin(b, key):
        return False
    label = re.escape(b.labels[key.controls[0]].text)
    if not label:
        return False
    unit = b.manual.units[at]
    held = hold_cells(unit) + [c for c in unit.cells if re.match(rf"\W*{HOLD_CELL}", c, re.I)]
    if unit.cells:
        if key.skill == "press":
            return (
                bool(held)
                and _in_cells(values, held)
                and not _in_cells(values, [c for c in unit.cells if c not in held])
            )
        return bool(held) and not _in_cells(values, held)
    if key.skill == "hold":
        return False
    text = _said_with(b, at, b.labels[key.controls[0]].text)
    holds = re.search(
        rf"\bhold(?:s|ing)?(?:\s+down)?\s+(?:the\s+)?{label}(?!\w)"
        rf"|(?<!\w){label}\s*\(?\s*(?:(?:press|touch|push)\s+and\s+)?hold",
        text,
        re.I,
    )
    presses = re.search(
        rf"\b{_PRESSING}\s+(?:the\s+)?{label}(?!\w)(?!\s+(?:and|to)\s+hold)", text, re.I
    )
    return bool(holds) and not presses


def _said_with(b: Builder, at: int, label: str) -> str:
    """Unit ``at`` with the sentences before it in the same paragraph or item, back to the one
    naming the key ("Hold LIGHT for 3 s to change the colour. Each hold selects …")."""
    units = b.manual.units
    said = [units[at].text]
    k = at
    while label.lower() not in said[0].lower() and k > 0 and len(said) < 3:
        before = units[k - 1]
        if (
            units[k].bullet
            or before.cells
            or before.heading != units[at].heading
            or units[k].line - before.line > 1
        ):
            break
        said.insert(0, before.text)
        k -= 1
    return " ".join(said)


def list_of_earlier_key(b: Builder, key: ActionInfo, at: int | None) -> bool:
    """Whether the list at unit ``at`` belongs to another key told just before it: a line naming
    no key, whose nearest key sentence above it in its section names another key only, while
    this key is named in that section only below the list ("ROTATE turns the design … r0° →
    r90° … MIRROR flips it": under "Rotating and mirroring" the angles are ROTATE's)."""
    if at is None or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return False
    units = b.manual.units
    heading = units[at].heading
    named: dict[int, set[str]] = {}
    for token, label in b.labels.items():
        for i in label.mentions:
            if units[i].heading == heading:
                named.setdefault(i, set()).add(token)
    own = key.controls[0]
    if at in named or not any(own in t for t in named.values()):
        return False
    if any(i < at and own in t for i, t in named.items()):
        return False
    before = [i for i in named if i < at]
    return bool(before) and own not in named[max(before)]


def held_section_list(b: Builder, key: ActionInfo) -> tuple[list[str], int] | None:
    """The list of a section where this key is only held, for a key also pressed short: a
    manual gives each job of the key its own section ("Automatic switch-off: 30 min → 60 min →
    90 min → 30 min …", then "Press and hold HAIR TYPE for 3 seconds"), and there the list is
    the hold's, wherever it stands in the section, even before the key is named. A section that
    also presses the key short is the press's (or both keys'): nothing is read from it; a
    sentence setting the press against the hold ("A short press still changes the type; only
    the hold sets the time") is about both."""
    from apbot.read.value_lists import find_list

    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return None
    if not _twin(b, key):
        return None
    label = b.labels[key.controls[0]].text
    if not label:
        return None
    lab = re.escape(label)
    holds = re.compile(
        rf"\bhold(?:s|ing)?(?:\s+down)?\s+(?:the\s+)?{lab}(?!\w)"
        rf"|\b(?:press|touch|push|tap)\s+and\s+hold\s+(?:the\s+)?{lab}(?!\w)",
        re.I,
    )
    presses = re.compile(
        rf"\b{_PRESSING}\s+(?:of\s+)?(?:the\s+)?{lab}(?!\w)(?!\s+(?:and|to)\s+hold)", re.I
    )
    units = b.manual.units
    sections: dict[str, list[int]] = {}
    for i, unit in enumerate(units):
        if unit.heading and unit.text != unit.heading:
            sections.setdefault(unit.heading, []).append(i)
    for i in b.labels[key.controls[0]].mentions:
        heading = units[i].heading
        if not heading or not holds.search(units[i].text):
            continue
        body = sections.get(heading, [])
        if any(
            presses.search(units[k].text) and not re.search(r"\bhold", units[k].text, re.I)
            for k in body
            if key.controls[0] in {t for t, lb in b.labels.items() if k in lb.mentions}
        ):
            continue  # the section presses the key too: not the hold's alone
        for k in body:
            if units[k].cells:
                continue
            found = find_list(units[k].text)
            if found and found[1] == "arrows" and comes_round(found[0], units[k].text):
                return found[0], k
    return None
