"""Display codes that carry an amount of time: "b30 … b120  boost minutes remaining", "SLP 90 …
SLP 15  sleep timer minutes".

A small display prints a timed setting as a letter or two and the number ("b60", "SLP 45"), and
the manual's display legend says once what the number counts. The user asks for the time ("a
half-hour boost", "a 45-minute sleep timer"), never the code, so a setting read as such codes
takes the amounts as its values ("30 min") and keeps each code as what the display shows; a code
for none ("SLP OFF", "no repeat") is the value off. The legend may put the unit in brackets
after the codes ("t OFF, t8, t15, t30 (minutes)") or repeat the codes' own numbers with it
("d1 / d2 / d3  repeat every 1 / 2 / 3 days"), and a code may carry its unit's letter itself
("W 1d … W 7d": days), which needs no legend. Codes naming programmes (P1 … P6, A1 …) have no
such legend line or unit and stay codes (:mod:`apbot.read.codes` names them by their chart).
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.code_words import own_lines
from apbot.read.off_words import unit_at
from apbot.read.values_stepped import MINUTES_HOURS

# a code of one to three letters and a number, the same letters on every value ("b30", "slp 90")
# (and maybe its unit's letter: "w 1d", "b 2h")
_CODE = re.compile(r"([a-z]{1,3}) ?(\d{1,3})([dh])?")
# a code for none: "slp off", "off", "no repeat"
_OFF = re.compile(r"(?:([a-z]{1,3})[ -])?off|no [a-z]+")  # ("A-OFF": the letters, a hyphen)
# the legend's count after the codes: "… boost minutes remaining", "… sleep timer minutes"
_COUNTS = re.compile(rf"\b({MINUTES_HOURS}|days?)\b", re.IGNORECASE)
_UNIT_WORD = {"min": "minutes", "h": "hours", "d": "days"}


def read_code_amounts(b: Builder) -> None:
    """Give a setting whose values are all codes of one prefix and a number the amounts the
    display legend says those numbers count, the codes as what the display shows."""
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        if spec.get("type") != "discrete" or spec.get("show") or len(values) < 3:
            continue
        coded = [m for v in values if (m := _CODE.fullmatch(v))]
        offs = [m for v in values if (m := _OFF.fullmatch(v))]
        prefixes = {m.group(1) for m in coded} | {m.group(1) for m in offs if m.group(1)}
        if len(coded) < 3 or len(coded) + len(offs) != len(values) or len(prefixes) != 1:
            continue
        suffixes = {m.group(3) for m in coded}
        if len(suffixes) != 1:
            continue
        suffix = suffixes.pop()
        if suffix:  # the codes print their unit: no legend needed
            found = _printed_unit(own_lines(b), coded[0].group(0), suffix)
        else:
            numbers = [m.group(2) for m in coded]
            found = _legend_unit(own_lines(b), coded[0].group(0), coded[-1].group(0), numbers)
            found = found or _row_units(own_lines(b), coded)
        if found is None:
            continue
        unit, line, letters = found
        names = {m.group(0): f"{m.group(2)} {unit}" for m in coded}
        names |= {m.group(0): "off" for m in offs}
        _rename(b, var, spec, names, letters, own_lines(b))
        b.note(
            f"variables.{var}.values",
            f"codes counting {_UNIT_WORD[unit]}: "
            + ", ".join(f"{c} {n}" for c, n in names.items()),
            unit_at(b, line + 1),
        )  # fmt: skip


def _printed(code: str) -> str:
    """A pattern for a code as a manual prints it, the space between letters and number optional."""
    return r"\b" + re.escape(code).replace(r"\ ", r"\s?") + r"\b"


def _printed_unit(lines: list[str], first: str, unit: str) -> tuple[str, int, str] | None:
    """The unit a code prints itself ("W 1d"), the first line printing the code, its letters."""
    pattern = re.compile(_printed(first), re.IGNORECASE)
    letters = len(first.split(" ")[0].rstrip("0123456789dh"))
    for i, line in enumerate(lines):
        m = pattern.search(line)
        if m is not None:
            return unit, i, line[m.start() : m.start() + letters]
    return None


def _legend_unit(
    lines: list[str], first: str, last: str, numbers: list[str]
) -> tuple[str, int, str] | None:
    """The unit a legend line counts after printing the first and the last code ("b30 … b120
    ....... boost minutes remaining", "t8, t15, t30 (minutes)"), the line's index and the
    codes' letters as printed."""
    pattern = re.compile(_printed(first) + r".{0,12}?" + _printed(last), re.IGNORECASE)
    letters = len(first.split(" ")[0].rstrip("0123456789"))
    for i, line in enumerate(lines):
        m = pattern.search(line)
        if m is None:
            continue
        # the legend's first clause names what it counts, no number in it ("… programmes
        # (P4: 30 minutes quick wash)", "… levels; the fan runs on 2 minutes" count no minutes)
        # — or the codes' own numbers ("d1 / d2 / d3  every 1 / 2 / 3 days"); a unit in
        # brackets right after the codes is the clause ("t8 … t60 (minutes)")
        rest = line[m.end() :]
        bracket = re.match(r"\s*\(([^()]*)\)", rest)
        clause = bracket.group(1) if bracket else re.split(r"[;:(),=]", rest)[0]
        said = re.findall(r"\d+", clause)
        counts = None if said and said != numbers else _COUNTS.search(clause)
        if counts is not None:
            word = counts.group(1).lower()
            unit = "h" if word.startswith("h") else "d" if word.startswith("d") else "min"
            return unit, i, line[m.start() : m.start() + letters]
    return None


def _row_units(lines: list[str], coded: list[re.Match[str]]) -> tuple[str, int, str] | None:
    """The unit a chart gives each code on its own row, beside the code's own number ("A10 |
    10 minutes", "A20   20 minutes"): every code's row counts the same unit."""
    units: set[str] = set()
    first: tuple[int, str] | None = None
    for m in coded:
        pattern = re.compile(
            _printed(m.group(0)) + rf"\s*(?:\||\s{{2,}}|[:=–-])\s*{m.group(2)}\s*"
            rf"({MINUTES_HOURS}|days?)\b",
            re.IGNORECASE,
        )
        row = next(((i, r) for i, line in enumerate(lines) if (r := pattern.search(line))), None)
        if row is None:
            return None
        word = row[1].group(1).lower()
        units.add("h" if word.startswith("h") else "d" if word.startswith("d") else "min")
        if first is None:
            letters = len(m.group(1))
            first = row[0], lines[row[0]][row[1].start() : row[1].start() + letters]
    if len(units) != 1 or first is None:
        return None
    return units.pop(), first[0], first[1]


def _rename(
    b: Builder,
    var: str,
    spec: dict[str, Any],
    names: dict[str, str],
    letters: str,
    lines: list[str],
) -> None:
    """Values become amounts; the display shows each code as the manual prints it ("W 1d",
    "t OFF"), else in the letters' case (a plain "off" or a "no repeat" in words keeps the
    display it had); settings per value are keyed by the amounts too."""
    spec["values"] = [names.get(str(v), v) for v in spec["values"]]
    if spec.get("initial") is not None:
        spec["initial"] = names.get(str(spec["initial"]), spec["initial"])
    upper = letters.isupper()
    spec["show"] = {
        n: _as_printed(lines, c) or (c.upper() if upper else c)
        for c, n in names.items()
        if c != n and not c.startswith("no ")
    }
    for child in b.variables.values():
        if child.get("depends_on") == var and "cases" in child:
            child["cases"] = {names.get(str(k), k): c for k, c in child["cases"].items()}


def _as_printed(lines: list[str], code: str) -> str | None:
    """The code as the manual prints it ("W 1d" for "w 1d"), from its first whole mention."""
    pattern = re.compile(r"(?<![\w-])" + re.escape(code) + r"(?![\w-])", re.IGNORECASE)
    for line in lines:
        m = pattern.search(line)
        if m is not None:
            return m.group(0)
    return None
