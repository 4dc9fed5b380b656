"""Numbered codes a chart names: a key that steps "Fn 1 > Fn 2 > Fn 3 > Fn 4" where a chart pairs
each code with a name ("| Fn 2 | Fischer (increment) | … |").

A small display numbers a setting's choices with a short prefix (Fn, P, F, A), and the step
sentence only gives the numbers, so the setting is first read as a count 1–N (or as the codes
themselves, "p 1", "p 2", which codes.py leaves for the space in them). A user asks for
the name ("a Fischer game"), never the number: when a chart has a column holding every code
"<prefix> 1" … "<prefix> N" and a column of names beside it, and the sentence the count was read
from prints the codes with that same prefix, the count becomes a choice of those names, the
display showing each one's code as printed. (Codes read as a list of words are codes.py's.)
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_tables import TRAILING_REMARK_RE, _norm, _tables
from apbot.read.text import Unit

# a numbered code as a chart cell prints it: "Fn 1", "P3", "F-2"
_NUMBERED = re.compile(r"([A-Za-z]{1,3})\s?-?(\d{1,2})")
_NAME = re.compile(r"[a-z][a-z '&/+-]{1,30}")


def name_numbered_codes(b: Builder) -> None:
    """Give a count 1–N stepped as prefixed codes the names a chart pairs the codes with."""
    for var, spec in b.variables.items():
        high = _count(spec)
        if high is None or spec.get("show"):
            continue
        quotes = [n.quote for n in b.notes if n.subject.startswith(f"variables.{var}") and n.quote]
        found = _chart(b, high, quotes)
        if found is None:
            continue
        names, shown, row = found
        _rename(spec, names, shown)
        b.note(
            f"variables.{var}.values",
            "numbered codes named by the chart: "
            + ", ".join(f"{shown[k]} {names[k]}" for k in sorted(names)),
            b.manual.units.index(row),
        )


def _count(spec: dict[str, Any]) -> int | None:
    """N for a setting read as the count 1–N, or as the codes "p 1" … "p N" in order."""
    if spec.get("type") == "discrete":
        values = [str(v) for v in spec.get("values") or []]
        codes = [_NUMBERED.fullmatch(v) for v in values]
        if not 2 <= len(values) <= 12 or not all(codes):
            return None
        numbers = [int(c.group(2)) for c in codes if c]
        if numbers != list(range(1, len(values) + 1)) or len({c.group(1) for c in codes if c}) != 1:
            return None
        return len(values)
    ranges = spec.get("ranges") or []
    if spec.get("type") != "numeric" or spec.get("unit") or len(ranges) != 1:
        return None
    low, high, step = [*ranges[0], 1][:3]
    return int(high) if low == 1 and step == 1 and 2 <= high <= 12 else None


def _chart(
    b: Builder, count: int, quotes: list[str]
) -> tuple[dict[int, str], dict[int, str], Unit] | None:
    """Names and printed codes of 1…``count``, from the first chart with a column of them whose
    prefix the count's own sentence prints ("Fn 1 > Fn 2 …")."""
    for _header, rows in _tables(b.manual.units):
        width = min(len(r.cells) for r in rows)
        for column in range(width - 1):
            codes: dict[int, tuple[str, str]] = {}  # number -> (prefix, as printed)
            for r in rows:
                m = _NUMBERED.fullmatch(r.cells[column].strip())
                if m:
                    codes.setdefault(int(m.group(2)), (m.group(1).lower(), r.cells[column].strip()))
            prefixes = {p for p, _ in codes.values()}
            if set(codes) != set(range(1, count + 1)) or len(prefixes) != 1:
                continue
            prefix = prefixes.pop()
            said = re.compile(
                rf"\b{re.escape(prefix)}\s?-?1\b.*\b{re.escape(prefix)}\s?-?2\b", re.I
            )
            if not any(said.search(q) for q in quotes):
                continue
            names = _names(rows, column + 1, codes)
            if len(names) == count and len(set(names.values())) == count:
                return names, {k: printed for k, (_, printed) in codes.items()}, rows[0]
    return None


def _names(rows: list[Unit], column: int, codes: dict[int, tuple[str, str]]) -> dict[int, str]:
    """Each number's name in ``column`` of its code's row ("Fischer (increment)": fischer)."""
    names: dict[int, str] = {}
    for r in rows:
        m = _NUMBERED.fullmatch(r.cells[column - 1].strip())
        if not m or column >= len(r.cells):
            continue
        name = TRAILING_REMARK_RE.sub("", _norm(r.cells[column]).split(" / ")[0]).strip()
        if _NAME.fullmatch(name) and not _NUMBERED.fullmatch(name):
            names.setdefault(int(m.group(2)), name)
    return names


def _rename(spec: dict[str, Any], names: dict[int, str], shown: dict[int, str]) -> None:
    """The count becomes a choice of the names in number order, each shown as its code."""
    initial = spec.get("initial")
    if isinstance(initial, str) and (code := _NUMBERED.fullmatch(initial)):
        initial = code.group(2)  # ("p 2": the second)
    for key in ("ranges", "step", "unit", "initial"):
        spec.pop(key, None)
    if spec.get("wrap") is True:
        spec.pop("wrap")  # (a choice steps round by default; a stop at the end is kept)
    spec["type"] = "discrete"
    spec["values"] = [names[k] for k in sorted(names)]
    spec["show"] = {names[k]: shown[k] for k in sorted(names)}
    if initial is not None and int(initial) in names:
        spec["initial"] = names[int(initial)]
