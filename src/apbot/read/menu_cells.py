"""Value cells of a settings-menu table row that prose readers do not take (see ``roles_menu``).

A menu-code table converted from a PDF prints each item's values tersely in a "Range" or
"Values" cell, in forms that never stand in running text: coded choices ("0 = off, 1 = on":
the display prints the code, the user says the name), a slash list of short display words
("C / F", "no / yES") and a bare step after the range ("7 – 60, step 1"). In prose "step 1"
numbers a procedure, so these are read only in a menu row's own cell.
"""

from __future__ import annotations

import re

from apbot.read.values import NUM, UNIT, number, unit_name

_CODED = re.compile(
    r"(?P<code>[0-9A-Za-z]{1,3})\s*=\s*(?P<name>[A-Za-z][A-Za-z ]{0,20}?)\s*(?:[,;/]|$)"
)
_SLASHED = re.compile(r"^\s*[A-Za-z0-9°]{1,6}(?:\s*/\s*[A-Za-z0-9°]{1,6})+\s*$")
_BARE_STEP = re.compile(rf"\bsteps?\s+({NUM})\s*({UNIT})?(?!\w)", re.IGNORECASE)
# a column headed as the code a small display prints before the value ("| Code | Setting |
# Values |", "| Display | … |"): the one test of a coded chart, for the settings-menu reader
# (roles_menu) and the walk of coded fields (code_walks) alike
CODE_HEAD = re.compile(r"^\W*(?:codes?|display(?:\s+codes?)?)\W*$", re.IGNORECASE)
# a choice printed as the symbol the display draws, then its name ("△ nasal", "▽ full face")
_DRAWN = re.compile(r"([^\w\s(),]{1,3})\s+([A-Za-z][A-Za-z -]{1,30})")


def drawn_choice(item: str) -> tuple[str, str] | None:
    """(symbol, name) of a listed choice drawn as a symbol before its name ("△ nasal" → ("△",
    "nasal")): the user says the name, the display shows the symbol. One reading for a menu
    item's values and a walked chart's fields."""
    m = _DRAWN.fullmatch(item.strip())
    return (m.group(1), m.group(2).strip()) if m else None


def coded_choices(cell: str) -> list[tuple[str, str]] | None:
    """[(code, name)] of a cell that is nothing but coded choices ("0 = off, 1 = on"), else None."""
    found = [(m.group("code"), m.group("name").strip()) for m in _CODED.finditer(cell)]
    rest = _CODED.sub("", cell).strip(" ,;/")
    if len(found) < 2 or rest:
        return None
    return found


def slashed_words(cell: str) -> list[str] | None:
    """The choices of a cell that is only short words joined by slashes ("C / F"), not
    numbers alone (a "1/2" is a fraction)."""
    if not _SLASHED.match(cell):
        return None
    parts = [p.strip() for p in cell.split("/")]
    if all(re.fullmatch(r"\d+", p) for p in parts):
        return None
    return parts


def bare_step(cell: str) -> tuple[float, str] | None:
    """The step a menu cell gives after its range ("7 – 60, step 1"): (size, unit)."""
    m = _BARE_STEP.search(cell)
    if m is None or not (value := number(m.group(1))):
        return None
    return value, unit_name(m.group(2) or "")
