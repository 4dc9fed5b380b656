"""A scale of levels the display prints as codes: "heat level (H2 … H9)", "T1 … T7  slush
thickness", "L1 (easiest) … L16 (hardest)".

A small display often shows a level as a letter and its number, and a manual then gives the
scale only as its first and last code, in a display legend or beside the setting's name. A
setting the manual gives no range for in numbers (the reader would guess one) takes the numbers
of the widest such span written where the setting is named, each shown as the code. A code
span standing for programmes (P1–P6) is left alone: it is read only for a numeric setting, and
only in a sentence or legend row naming that setting. Fault codes ("E1 … E9" in a trouble
table or a sentence about errors) and model ranges ("models HP1 – HP5", "BM1 - BM3 series",
"type TR2 - TR4") are no scale.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.code_words import MODELS_RE
from apbot.read.labels import words
from apbot.read.shapes import ASIDE_HEADING

# a sentence about faults: its codes are error codes, not a setting's levels
_FAULT_RE = re.compile(r"\b(?:errors?|faults?|faulty|malfunction\w*|failures?)\b", re.IGNORECASE)

# a range of parts or products, like a model range: "BM1 - BM3 series", "type TR2 - TR4"
_SERIES_RE = re.compile(r"\bseries\b|\btypes?\s+[A-Z]{1,2}\d", re.IGNORECASE)

# "H2 … H9", "T1 - T7", "L1 (easiest) … L16 (hardest)": one prefix, its first and last number
_SPAN = re.compile(
    r"(?<![\w-])(?P<code>[A-Z]{1,2})(?P<low>\d{1,2})(?:\s*\([^()\d]{1,20}\))?"
    r"\s*(?:…|\.{3}|–|—|-|to)\s*(?P=code)(?P<high>\d{1,2})(?![\w.,]\d|\d)"
)


def code_spans(text: str) -> list[tuple[str, int, int]]:
    """The code spans in a text: (prefix, first number, last number), the first lower."""
    return [
        (m["code"], int(m["low"]), int(m["high"]))
        for m in _SPAN.finditer(text)
        if int(m["low"]) < int(m["high"])
    ]


def read_code_levels(b: Builder) -> None:
    """Give a numeric setting whose range was guessed the scale a code span names for it."""
    for var, spec in b.variables.items():
        if var not in b.unread or spec.get("type") != "numeric" or "cases" in spec:
            continue
        own = {w[:5] for w in words(var.replace("_", " ")) + words(str(spec.get("label") or ""))}
        own = {w for w in own if len(w) >= 4}
        if not own:
            continue
        best: tuple[int, str, int, int, int] | None = None  # (width, code, low, high, unit)
        for i, unit in enumerate(b.manual.units):
            if not own & {w[:5] for w in words(unit.text)} or _aside(unit.text, unit.heading):
                continue
            for code, low, high in code_spans(unit.text):
                if best is None or high - low > best[0]:
                    best = (high - low, code, low, high, i)
        if best is None:
            continue
        _, code, low, high, at = best
        spec["ranges"] = [[low, high, 1]]
        spec["unit"] = ""
        spec["show"] = f"{code}{{value}}"
        if spec.get("initial") is not None and not low <= float(spec["initial"]) <= high:
            spec.pop("initial")
        b.unread.discard(var)
        subject = f"variables.{var}"
        b.notes = [
            n for n in b.notes if not (n.guess and n.subject in (subject, f"{subject}.step"))
        ]
        b.note(subject, f"levels {low}–{high}, shown {code}{low} … {code}{high}", at)


def _aside(text: str, heading: str) -> bool:
    """Whether a unit's codes are faults or models: under a trouble or safety heading, or in a
    sentence about errors or naming models, a series or a type."""
    return bool(
        ASIDE_HEADING.search(heading)
        or _FAULT_RE.search(text)
        or MODELS_RE.search(text)
        or _SERIES_RE.search(text)
    )
