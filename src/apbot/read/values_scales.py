"""A scale of values printed on a line of its own under a sentence that introduces it, its
steps uneven: "Available temperatures (°C):" then "160 ── 180 ── 200 ── 210 ── 220 ── 230 ──
240", or "The available times are:" then a one-row table "| minutes | 4 | 6 | 8 | 10 | 15 |
20 | 25 | 30 |". Every value is one stop of the setting, so the scale is its pieces, each run
of equal gaps one piece with that step (160–200 by 20, 200–240 by 10). An even scale is one
range, which values.py already reads; only the uneven ones are read here.
"""

from __future__ import annotations

import re

from apbot.read.text import Unit
from apbot.read.values import UNIT, Range, gap_pieces, number, unit_name

# a run of one separator between numbers: dashes drawn as a line ("──", "--", "–"), arrows
# ("→", "->") or table cells ("|"), the same one each time
_SEPARATOR = r"\s*(?:[-─—–]+>?|→|►|\|)\s*"
_NUMBER = r"\d+(?:[.,]\d+)?"
_SCALE_RE = re.compile(
    rf"^(?:(?P<lead>{UNIT})\s*\|\s*)?(?P<run>{_NUMBER}(?:{_SEPARATOR}{_NUMBER}){{3,}})"
    rf"\s*(?P<unit>{UNIT}(?![\w]))?",
    re.IGNORECASE,
)
_BRACKET_UNIT_RE = re.compile(rf"\(\s*({UNIT})\s*\)\s*:\s*$", re.IGNORECASE)


def scale_pieces(units: list[Unit], i: int) -> list[Range]:
    """The pieces of an uneven scale printed right under the sentence ``units[i]`` that ends
    with a colon (its unit after the last value, in a first cell, or in brackets before the
    colon: "Available temperatures (°C):"); else [], and [] for a scale in no unit (a row of
    wattages, years or pages under a sentence is no setting's stops)."""
    said = units[i].text.rstrip()
    if not said.endswith(":") or i + 1 >= len(units):
        return []
    m = _SCALE_RE.match(units[i + 1].text.strip())
    if m is None:
        return []
    separators = {s.strip() for s in re.findall(_SEPARATOR, m.group("run"))}
    if len(separators) != 1:
        return []  # "4 – 6 | 8": two kinds of joins, no one scale
    figures = [number(x) for x in re.findall(_NUMBER, m.group("run"))]
    values = [x for x in figures if x is not None]
    if len(values) != len(figures) or values != sorted(set(values)):
        return []  # a scale climbs; "022 → 018 → 010" are codes, not stops
    bracket = _BRACKET_UNIT_RE.search(said)
    unit = unit_name(m.group("unit") or m.group("lead") or (bracket and bracket.group(1)))
    if not unit:
        return []  # "sold in these sizes:" 1200 ── 1500 ── …, "the years:" 2019 ── 2020 ── …
    return uneven_pieces(values, unit)


def uneven_pieces(values: list[float], unit: str) -> list[Range]:
    """Runs of equal gaps as pieces, each with its gap as the step, when there are two or more
    of them (160, 180, 200, 210, 220 → 160–200 by 20, 200–220 by 10); else []."""
    pieces = gap_pieces(values, unit)
    return pieces if len(pieces) >= 2 else []


def spans_read(pieces: list[Range], ranges: list[Range]) -> bool:
    """Whether a scale spans what was read before it (nothing, or ranges in its unit, or in
    none, from its low end to its high end): the scale then says more, its steps included. A
    scale reaching past a range read before it is another's ("On the XL the temperatures
    are:"), or the range says less than the scale's ends; the range stated holds."""
    if not ranges:
        return True
    unit = pieces[0].unit
    return all(r.unit in ("", unit) for r in ranges) and (
        min(r.low for r in ranges),
        max(r.high for r in ranges),
    ) == (pieces[0].low, pieces[-1].high)


def beyond(pieces: list[Range], ranges: list[Range]) -> Range | None:
    """A range read after a scale that reaches past its ends in its unit ("Suggested times
    (min):" 8 | 12 | 15 | 25, then "from 1 to 60 minutes"): the scale was a guide's stops,
    the range is the setting's; else None."""
    low, high, unit = pieces[0].low, pieces[-1].high, pieces[0].unit
    for r in ranges:
        if (
            r.unit in ("", unit)
            and r.low <= low
            and high <= r.high
            and (r.low, r.high) != (low, high)
        ):
            return r
    return None
