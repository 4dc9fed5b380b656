"""Display codes the manual spells out as words: "S / M / L  cube size (small, medium, large)".

A panel with lamps or a small display prints a setting as letter codes (S / M / L, W+B / W / B,
LO / HI), and the manual says once what each code stands for: a legend line that lists the codes
and then the words in the same order, or a line per code ("S - small cubes", "W   white LEDs
only"). The user says the word ("large cubes", "blue only"), never the code, so a setting read as
codes takes the words as its values and keeps the codes as what the display shows.

Only words the codes abbreviate count: every letter group of a code must begin a word of its
meaning, in order ("W+B" → "white and blue", "LO" → "low"). Charts pairing codes that abbreviate
nothing (A1 → CLASSIC) are :mod:`apbot.read.codes`' job.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.codes import rename_codes
from apbot.read.off_words import lines_outside_asides, unit_at

# a display code: one or two letters, or such groups joined by "+" ("W+B"); not three ("ECO",
# "MAX" are words users say themselves)
_CODE = re.compile(r"[a-z]{1,2}(?:\+[a-z]{1,2})*")
# a code of letters, maybe with a digit ("d2"), each glossed in brackets in a run of arrows
_NUMBERED = re.compile(r"[a-z]{1,2}\d?")
_GLOSS = r"\s*\(([a-z][a-z' -]{1,20})\)"
_WORD = re.compile(r"[A-Za-z][A-Za-z'-]*")
_NOT_CODES = frozenset({"on", "off"})
_LEAD = 4  # a definition's words: the code's meaning comes first ("S - small cubes, …")
_ITEMS = re.compile(r"\s*[/,;]\s*|\s+or\s+")
# a line naming models or versions: its codes are the models' ("Models S / M / L (standard, …)")
MODELS_RE = re.compile(r"\b(?:models?|versions?|variants?)\b", re.IGNORECASE)


def name_code_words(b: Builder) -> None:
    """Give a setting whose values are all letter codes the words the manual spells them as."""
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        if spec.get("type") != "discrete" or not 2 <= len(values) <= 8 or spec.get("show"):
            continue
        if set(values) <= _NOT_CODES:
            continue
        lines = own_lines(b)
        if all(_CODE.fullmatch(v) for v in values):
            found = _legend_words(lines, values) or _definition_words(lines, values)
        else:
            found = None
        if not found and all(_NUMBERED.fullmatch(v) for v in values):
            found = _bracketed_words(lines, values)
        if not found:
            continue
        names, line = found
        rename_codes(b, var, spec, names)
        b.note(
            f"variables.{var}.values",
            "codes spelt out by the manual: " + ", ".join(f"{c} {n}" for c, n in names.items()),
            unit_at(b, line),
        )


def own_lines(b: Builder) -> list[str]:
    """The manual's lines, blanked where codes are no setting's: under a troubleshooting,
    error-code or safety heading, or on a line naming models ("Models S / M / L")."""
    return ["" if MODELS_RE.search(line) else line for line in lines_outside_asides(b)]


def _meaning(code: str, words: list[str]) -> str | None:
    """The words from the first to the last that the code's letter groups begin, in order
    ("W+B", "white and blue LEDs" → "white and blue"), or None."""
    parts = code.split("+")
    lowered = [w.lower() for w in words]
    first = last = -1
    k = 0
    for i, word in enumerate(lowered):
        if k < len(parts) and len(word) > len(parts[k]) and word.startswith(parts[k]):
            first = i if first < 0 else first
            last = i
            k += 1
    if k < len(parts):
        return None
    return " ".join(lowered[first : last + 1])


def _legend_words(lines: list[str], codes: list[str]) -> tuple[dict[str, str], int] | None:
    """A line listing the codes ("S / M / L", "W+B / W / B") then, after a colon or in
    brackets, as many items in the same order, each one the words a code abbreviates."""
    printed = r"\s*/\s*".join(re.escape(c.upper()) for c in codes)
    head = re.compile(rf"(?<![\w+]){printed}(?![\w+])")
    for number, line in enumerate(lines, 1):
        match = head.search(line)
        if not match:
            continue
        rest = line[match.end() :]
        for segment in re.split(r"[():]", rest):
            items = [i for i in _ITEMS.split(segment.strip(" .")) if i]
            if len(items) != len(codes):
                continue
            names = [_meaning(c, _WORD.findall(i)) for c, i in zip(codes, items, strict=True)]
            if all(names) and len(set(names)) == len(codes):
                return {c: str(n) for c, n in zip(codes, names, strict=True)}, number
    return None


def _definition_words(lines: list[str], codes: list[str]) -> tuple[dict[str, str], int] | None:
    """Lines each led by one code and its meaning ("S - small cubes", "W   white LEDs only")."""
    names: dict[str, str] = {}
    first = 0
    for code in codes:
        lead = re.compile(rf"^\s*(?:[-•▪*]\s*)?{re.escape(code.upper())}(?:\s*[-–—:=]\s*|\s+)(.*)")
        for number, line in enumerate(lines, 1):
            match = lead.match(line)
            if not match:
                continue
            name = _meaning(code, _WORD.findall(match.group(1))[:_LEAD])
            if name:
                names[code] = name
                first = first or number
                break
    if len(names) == len(codes) and len(set(names.values())) == len(codes):
        return names, first
    return None


def _bracketed_words(lines: list[str], codes: list[str]) -> tuple[dict[str, str], int] | None:
    """A line stepping through the codes, each with its word in brackets ("d2 (high) → d1
    (low) → d0 (off)", "L (left) → C (centre)"): the bracket pairs them, so a code need not
    abbreviate its word. Two lines glossing the same codes apart (two keys showing F1 … F3)
    leave it open which one is this setting's: no words then."""
    found: list[tuple[dict[str, str], int]] = []
    for number, line in enumerate(lines, 1):
        if "→" not in line and "->" not in line:
            continue
        names: dict[str, str] = {}
        for code in codes:
            m = re.search(rf"(?<![\w+]){re.escape(code)}{_GLOSS}", line, re.IGNORECASE)
            if m:
                names[code] = m.group(1).strip().lower()
        if len(names) == len(codes) and len(set(names.values())) == len(codes):
            found.append((names, number))
    return found[0] if found and all(f[0] == found[0][0] for f in found) else None
