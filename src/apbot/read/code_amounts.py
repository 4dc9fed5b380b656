"""Display codes that carry an amount of time: "b30 … b120  boost minutes remaining", "SLP 90 …
SLP 15  sleep timer minutes".

A small display prints a timed setting as a letter or two and the number ("b60", "SLP 45"), and
the manual's display legend says once what the number counts. The user asks for the time ("a
half-hour boost", "a 45-minute sleep timer"), never the code, so a setting read as such codes
takes the amounts as its values ("30 min") and keeps each code as what the display shows; a code
for none ("SLP OFF") is the value off. Codes naming programmes (P1 … P6, A1 …) have no such
legend line and stay codes (:mod:`apbot.read.codes` names them by their chart).
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.code_words import own_lines
from apbot.read.off_words import unit_at
from apbot.read.values_stepped import MINUTES_HOURS

# a code of one to three letters and a number, the same letters on every value ("b30", "slp 90")
_CODE = re.compile(r"([a-z]{1,3}) ?(\d{1,3})")
_OFF = re.compile(r"(?:([a-z]{1,3}) )?off")
# the legend's count after the codes: "… boost minutes remaining", "… sleep timer minutes"
_COUNTS = re.compile(rf"\b({MINUTES_HOURS})\b", re.IGNORECASE)


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
        found = _legend_unit(own_lines(b), coded[0].group(0), coded[-1].group(0))
        if found is None:
            continue
        unit, line, letters = found
        names = {m.group(0): f"{m.group(2)} {unit}" for m in coded}
        names |= {m.group(0): "off" for m in offs}
        _rename(b, var, spec, names, letters)
        b.note(
            f"variables.{var}.values",
            "codes counting " + ("minutes" if unit == "min" else "hours") + ": "
            + ", ".join(f"{c} {n}" for c, n in names.items()),
            unit_at(b, line + 1),
        )  # fmt: skip


def _legend_unit(lines: list[str], first: str, last: str) -> tuple[str, int, str] | None:
    """The unit a legend line counts after printing the first and the last code ("b30 … b120
    ....... boost minutes remaining"), the line's index and the codes' letters as printed."""

    def printed(code: str) -> str:
        return r"\b" + re.escape(code).replace(r"\ ", r"\s?") + r"\b"

    pattern = re.compile(printed(first) + r".{0,12}?" + printed(last), re.IGNORECASE)
    letters = len(first.split(" ")[0].rstrip("0123456789"))
    for i, line in enumerate(lines):
        m = pattern.search(line)
        if m is None:
            continue
        # the legend's first clause names what it counts, no number in it ("… programmes
        # (P4: 30 minutes quick wash)", "… levels; the fan runs on 2 minutes" count no minutes)
        clause = re.split(r"[;:(),=]", line[m.end() :])[0]
        counts = None if re.search(r"\d", clause) else _COUNTS.search(clause)
        if counts is not None:
            unit = "h" if counts.group(1).lower().startswith("h") else "min"
            return unit, i, line[m.start() : m.start() + letters]
    return None


def _rename(
    b: Builder, var: str, spec: dict[str, Any], names: dict[str, str], letters: str
) -> None:
    """Values become amounts; the display shows each code as the manual prints it, in the
    letters' case (a plain "off" keeps the display it had); settings per value are keyed by
    the amounts too."""
    spec["values"] = [names.get(str(v), v) for v in spec["values"]]
    if spec.get("initial") is not None:
        spec["initial"] = names.get(str(spec["initial"]), spec["initial"])
    upper = letters.isupper()
    spec["show"] = {n: c.upper() if upper else c for c, n in names.items() if c != n}
    for child in b.variables.values():
        if child.get("depends_on") == var and "cases" in child:
            child["cases"] = {names.get(str(k), k): c for k, c in child["cases"].items()}
