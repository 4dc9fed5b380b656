"""Display codes a table spells out in its next column: "| TRACK SID | sidereal | stars … |",
"| TRACK LUN | lunar | the Moon |" (a chart of what the display shows and what it means).

A setting read as three-letter codes (SID / LUN / SOL, from "SID → LUN → SOL → OFF") keeps
them as what the display shows and takes the words as its values, when each code is the start
of the word its row gives ("SID" of "sidereal"): the user says "lunar", never "LUN". Codes
of one or two letters are :mod:`apbot.read.code_words`' job (which leaves three-letter codes
alone: "ECO", "MAX" are words people say); a row whose word does not start with its code
("OFF | no tracking") keeps the code (OFF is a word). The display cell may lead with the key's
name ("TRACK SID"): the whole cell is what the display shows.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder

_CODE = re.compile(r"[a-z]{3,4}")
_KEEP = frozenset({"on", "off", "auto"})


def read_code_rows(b: Builder) -> None:
    """Give each discrete setting of display codes the words a table's rows spell them as."""
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        if spec.get("type") != "discrete" or spec.get("show") or not 2 <= len(values) <= 10:
            continue
        codes = [v for v in values if v not in _KEEP]
        if len(codes) < 2 or not all(_CODE.fullmatch(v) for v in codes):
            continue
        found = _rows(b, values)
        if found is None or not all(c in found[0] for c in codes):
            continue
        names, shows, at = found
        spec["values"] = [names.get(v, v) for v in values]
        if spec.get("initial") is not None:
            spec["initial"] = names.get(str(spec["initial"]), spec["initial"])
        spec["show"] = {names.get(v, v): shows.get(v, v.upper()) for v in values}
        b.note(
            f"variables.{var}.values",
            "display codes a table spells out: "
            + ", ".join(f"{shows[c]} {n}" for c, n in names.items()),
            at,
        )


def _rows(b: Builder, values: list[str]) -> tuple[dict[str, str], dict[str, str], int] | None:
    """The words and display cells of the one table whose rows give the codes: (code → word,
    code → cell, the first row's unit), or None."""
    names: dict[str, str] = {}
    shows: dict[str, str] = {}
    first = -1
    for i, unit in enumerate(b.manual.units):
        if len(unit.cells) < 2 or not unit.header:
            continue
        cell = unit.cells[0].strip()
        for v in values:
            if not re.fullmatch(rf"(?:[A-Z][A-Z-]{{1,9}}\s+)?{v.upper()}", cell):
                continue
            word = re.match(r"[a-z]+", unit.cells[1].strip().lower())
            if v in shows and shows[v] != cell:
                return None  # the code in two tables: which is the display's is not told
            shows[v] = cell
            if word and word[0].startswith(v) and len(word[0]) > len(v):
                names[v] = word[0]
                first = i if first < 0 else first
    if not names or len(set(names.values())) != len(names):
        return None
    return names, shows, first
