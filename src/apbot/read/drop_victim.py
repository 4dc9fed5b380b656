"""Which of two features sharing a first key the reader gives up when the checker objects.

The checker refuses a feature whose first step's keys already start another feature ("can never
start"). Two readings of one procedure often collide that way: a legend line ("hold 2 s: bonus
seconds") makes a feature whose amount is a pure guess, while the section's numbered steps make
another with the range the manual states. By default the refused feature goes; when the feature
that claimed the key holds only guessed ranges and the refused one holds ranges the manual
states, the guess goes instead — the reading with evidence is the one worth keeping.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.report import Note

_OWNERS_RE = re.compile(r"can never start: .* already starts \[([^\]]*)\]")


def feature_to_drop(data: dict[str, Any], refused: str, why: str, notes: list[Note]) -> str:
    """The feature to remove for the checker's complaint ``why`` about feature ``refused``."""
    m = _OWNERS_RE.search(why)
    if not m:
        return refused
    owners = [o.strip().strip("'\"") for o in m.group(1).split(",") if o.strip()]
    if len(owners) != 1 or owners[0] not in data["features"]:
        return refused
    owner = owners[0]
    if _ranges_said(data, refused, notes) and _ranges_guessed(data, owner, notes):
        return owner
    return refused


def _amounts(data: dict[str, Any], feature: str) -> set[str]:
    """The feature's variables that carry numeric ranges."""
    names = {s.get("variable") for s in data["features"].get(feature, [])}
    return {
        n
        for n in names
        if n and isinstance(data["variables"].get(n), dict) and data["variables"][n].get("ranges")
    }


def _range_notes(notes: list[Note], var: str) -> list[Note]:
    return [n for n in notes if n.subject == f"variables.{var}" and n.what.startswith("range")]


def _ranges_said(data: dict[str, Any], feature: str, notes: list[Note]) -> bool:
    amounts = _amounts(data, feature)
    return bool(amounts) and all(any(not n.guess for n in _range_notes(notes, v)) for v in amounts)


def _ranges_guessed(data: dict[str, Any], feature: str, notes: list[Note]) -> bool:
    amounts = _amounts(data, feature)
    return bool(amounts) and all(
        _range_notes(notes, v) and all(n.guess for n in _range_notes(notes, v)) for v in amounts
    )
