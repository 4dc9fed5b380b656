"""Programmes the key steps through as codes, named by the manual's chart.

Panels with a small display show a programme as a code ("P1 → P2 → … → P6"), and the manual's
programme chart pairs each code with its name ("| P3 | JERKY / MEAT | 70 °C |"). A user asks
for the name ("dry some jerky"), never the code, so a setting read as codes takes the names
from the chart as its values and keeps the codes as what the display shows. Codes of
letters alone ("A1 → A2 → SH → KN") are read so only from a chart column headed as the code
("| Code | Programme |"), where they cannot be names themselves. A name given two ways
("JERKY / MEAT") is called by the first: the goal parser matches whole names.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_tables import TRAILING_REMARK_RE, _norm, _tables
from apbot.read.text import Unit

_CODE = re.compile(r"[a-z]{1,3}\s?-?\d{1,2}")
_NAME = re.compile(r"[a-z][a-z '&/+-]{1,30}")
_SHORT = re.compile(r"[a-z0-9]{1,3}|[a-z]{1,3}\s?-?\d{1,2}")  # "sh", "a1", "p 3"
_BLANK = re.compile(r"-{1,3}")
_CODE_HEAD = re.compile(r"\b(?:codes?|display|shown|indication)\b", re.IGNORECASE)
# a word a small display prints, read only from a column headed as the code: up to four
# letters in one piece ("tHr", "rEAd", "SUN"), which may be words themselves
_HEADED_SHORT = re.compile(r"[a-z0-9]{1,4}")
_SEGMENT_CASE = re.compile(r"[a-z][A-Z]")  # "rEAd", "tHr": a capital after a small letter


def name_codes(b: Builder) -> None:
    """Give a setting whose values are all codes the names a chart's column pairs them with."""
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        if spec.get("type") != "discrete" or len(values) < 3:
            continue
        # dashes among the codes are the display's blank ("FRAME --": no frame), named too
        codes = [v for v in values if not _BLANK.fullmatch(v)]
        if spec.get("show") or len(values) - len(codes) > 1:
            continue
        if not all(_HEADED_SHORT.fullmatch(v) for v in codes):
            continue
        # codes of letters alone ("SH", "KN") only from a column headed as the code
        short = all(_SHORT.fullmatch(v) for v in codes)
        headed = not all(_CODE.fullmatch(v) for v in codes)
        found = _chart_names(b, values, headed=headed, segments=not short)
        if found:
            names, row = found
            rename_codes(b, var, spec, names)
            at = b.manual.units.index(row)
            b.note(
                f"variables.{var}.values",
                "codes named by the chart: " + ", ".join(f"{c} {n}" for c, n in names.items()),
                at,
            )


def _chart_names(
    b: Builder, codes: list[str], headed: bool = False, segments: bool = False
) -> tuple[dict[str, str], Unit] | None:
    """The names beside the codes in the first table with a column of every one of them
    (``headed``: a column whose header says it holds the codes, "Code", "Display";
    ``segments``: codes of four letters, which may be words, only where the column prints
    one as a segment display spells it, "rEAd", "tHr")."""
    for header, rows in _tables(b.manual.units):
        width = min(len(r.cells) for r in rows)
        for column in range(width):
            if headed and not (column < len(header) and _CODE_HEAD.search(header[column])):
                continue
            cells = [_norm(r.cells[column]) for r in rows]
            if not set(codes) <= set(cells):
                continue
            if segments and not any(_SEGMENT_CASE.search(r.cells[column]) for r in rows):
                continue
            names = _beside(rows, cells, codes, column + 1) if column + 1 < width else {}
            if headed and column > 0 and len(names) < len(codes):
                # "| Mode | Display |": a column headed as the code may follow the names
                names = _beside(rows, cells, codes, column - 1)
            if len(names) == len(codes) and len(set(names.values())) == len(codes):
                return names, rows[0]
    return None


def _beside(rows: list[Unit], cells: list[str], codes: list[str], column: int) -> dict[str, str]:
    """Each code's name in ``column`` of its row, where that cell is a name and no code."""
    names: dict[str, str] = {}
    for row, cell in zip(rows, cells, strict=True):
        if column >= len(row.cells):
            continue
        name = _norm(row.cells[column]).split(" / ")[0]  # "JERKY / MEAT": jerky
        name = TRAILING_REMARK_RE.sub("", name)  # "Soft steam (bio / combi)": a remark on it
        if cell in codes and _NAME.fullmatch(name) and not _CODE.fullmatch(name):
            names.setdefault(cell, name)
    return names


def rename_codes(b: Builder, var: str, spec: dict[str, Any], names: dict[str, str]) -> None:
    """Values become names; the display shows each one's code as the manual prints it;
    settings that depend on this one (per programme) are keyed by the names too."""
    spec["values"] = [names[str(v)] for v in spec["values"]]
    if spec.get("initial") is not None:
        spec["initial"] = names.get(str(spec["initial"]), spec["initial"])
    spec["show"] = {n: c.upper() for c, n in names.items()}
    for child in b.variables.values():
        if child.get("depends_on") == var and "cases" in child:
            child["cases"] = {names.get(str(k), k): c for k, c in child["cases"].items()}
