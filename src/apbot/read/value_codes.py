"""The short code the display shows for each named value of a setting.

A small display rarely prints a value's whole name: manuals pair each name with what the
display shows, either in a chart with a column headed as the code ("| Mode | Code | … |",
"| Colour | Display | … |") or in brackets after each name where the order is given
("ALWAYS ON (On) → DUSK TO DAWN (dd)", "MUTE → LOW (VOL LO) → HIGH (VOL HI)"). Without those
codes the agent cannot tell which value a reading such as "MIST L" or "dd" is. The reverse
case — values read as codes, names from a chart — is codes.py's.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.cases_tables import TRAILING_REMARK_RE, _norm, _tables
from apbot.read.code_levels import _FAULT_RE
from apbot.read.codes import _CODE_HEAD
from apbot.read.shapes import ASIDE_HEADING
from apbot.read.values import UNIT

# a code as printed: short, no comma, each word short or in capitals ("On", "dd", "VOL LO",
# "L-WA", "MIST H"); a bracket holding a lower-case word of four letters or more ("(full
# power)", "(candle)") glosses the name instead
_CODE_TEXT = re.compile(r"[^\s,;()]+(?: [^\s,;()]+)?")
_LAMP_HEAD = re.compile(r"\b(?:lamps?|leds?|lights?|icons?|symbols?)\b", re.IGNORECASE)
# an amount ("60 °C", "90 min", "1:59") says what a value does, not how the display names it
_AMOUNT = re.compile(rf"\d+(?:[.,]\d+)?\s*{UNIT}|\d{{1,2}}:\d{{2}}", re.IGNORECASE)
# a fault chart's heads ("| Programme | Code | Cause |"): its codes are error codes
_FAULT_HEAD = re.compile(r"\b(?:causes?|remed(?:y|ies)|solutions?)\b", re.IGNORECASE)


def _code_like(text: str) -> bool:
    if not 1 <= len(text) <= 8 or not _CODE_TEXT.fullmatch(text) or _AMOUNT.fullmatch(text):
        return False
    # a word in capitals, a short one, or one a segment display spells in mixed case ("rEAd",
    # "StdY": a capital after a small letter, as no word is written)
    return all(
        len(w) <= 3 or w.upper() == w or re.search(r"[a-z][A-Z]", w)
        for w in re.findall(r"[A-Za-z]+", text)
    )


def read_value_codes(b: Builder) -> None:
    """Give each named setting without display words the codes the manual pairs its values
    with (a chart's code column first, else codes in brackets after the names)."""
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        if spec.get("type") != "discrete" or len(values) < 3 or spec.get("show"):
            continue
        if any(_code_like(v) and v.upper() == v for v in values):
            continue  # values that are codes already ("P1", "A2")
        found = _column_codes(b, values) or _bracket_codes(b, values)
        if found is None:
            continue
        shows, at = found
        spec["show"] = shows
        said = ", ".join(f"{v} {c}" for v, c in shows.items())
        b.note(f"variables.{var}.show", f"the display shows each value as a code: {said}", at)


def _column_codes(b: Builder, values: list[str]) -> tuple[dict[str, str], int] | None:
    """A chart with a column naming every value and a column headed as the code (not a lamp
    column, nor a fault chart's): each value's code is the cell in its row."""
    wanted = {v.lower() for v in values}
    for header, rows in _tables(b.manual.units):
        if ASIDE_HEADING.search(rows[0].heading or "") or any(
            _FAULT_RE.search(h) or _FAULT_HEAD.search(h) for h in header
        ):
            continue  # "TROUBLESHOOTING | Programme | Code | Cause": error codes
        width = min(len(r.cells) for r in rows)
        for column in range(width):
            names = [TRAILING_REMARK_RE.sub("", _norm(r.cells[column])) for r in rows]
            if not wanted <= set(names):
                continue
            for other in range(min(width, len(header))):
                head = header[other]
                if other == column or not _CODE_HEAD.search(head) or _LAMP_HEAD.search(head):
                    continue
                shows = {
                    n: r.cells[other].strip()
                    for n, r in zip(names, rows, strict=True)
                    if n in wanted
                }
                if _distinct_codes(shows, values):
                    return {v: shows[v.lower()] for v in values}, b.manual.units.index(rows[0])
    return None


def _bracket_codes(b: Builder, values: list[str]) -> tuple[dict[str, str], int] | None:
    """One sentence naming every value, all but at most one followed by a code in brackets
    ("MUTE → LOW (VOL LO) → HIGH (VOL HI)"); a value without one shows its name as printed."""
    for at, unit in enumerate(b.manual.units):
        shows: dict[str, str] = {}
        for value in values:
            m = re.search(
                rf"(?<!\w)({re.escape(value)})(?!\w)(?:\s*\(([^()]*)\))?", unit.text, re.I
            )
            if m is None:
                break
            code = (m.group(2) or "").strip()
            shows[value] = code if _code_like(code) else m.group(1)
        if len(shows) < len(values):
            continue
        coded = sum(shows[v] != v and shows[v].lower() != v.lower() for v in values)
        if coded >= len(values) - 1 and _distinct_codes(shows, values):
            return shows, at
    return None


def _distinct_codes(shows: dict[str, str], values: list[str]) -> bool:
    """Every value has its own code, each a short code, not merely the name again."""
    codes = [shows.get(v.lower(), shows.get(v, "")) for v in values]
    if not all(_code_like(c) for c in codes) or len({c.lower() for c in codes}) < len(codes):
        return False
    return any(c.lower() != v.lower() for c, v in zip(codes, values, strict=True))
