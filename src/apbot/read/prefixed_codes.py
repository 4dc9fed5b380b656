"""Display codes made of the setting's own name and a letter: "OSC-N narrow … OSC-W wide".

A lamp panel prints each value of a setting as the setting's short name with a letter after a
dash (OSC-N / OSC-W / OSC-R, MODE-A / MODE-B), and the manual says once, in a line per code, what
the letter stands for ("OSC-W   wide: from one side to the other"). The user says the word
("wide oscillation"), never the code, so the values take the words as their names and keep the
codes as what the display shows. A value "off" among them is no code: it stays "off" and shows
nothing (no lamp lit).

Only the letter after the name counts, and it must begin the first word of the definition
(:func:`apbot.read.code_words._meaning` on the definition's lead words), so a code whose line
describes rather than names ("OSC-N alternates …") keeps its code.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.code_words import _meaning, own_lines
from apbot.read.codes import rename_codes
from apbot.read.labels import words as name_words
from apbot.read.off_words import unit_at

_WORD = re.compile(r"[A-Za-z][A-Za-z'-]*")
_OFF = "off"
_LEAD = 1  # the definition's first word is the value's name ("narrow: alternates …")


def name_prefixed_codes(b: Builder) -> None:
    """Give a setting whose values are NAME-letter codes the words the manual defines them as."""
    lines = own_lines(b)
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or []]
        if spec.get("type") != "discrete" or not 2 <= len(values) <= 8 or spec.get("show"):
            continue
        codes = [v for v in values if v != _OFF]
        stems = set(name_words(f"{var} {spec.get('label') or ''}"))
        letters = {c: _letter(c, stems) for c in codes}
        if len(codes) < 2 or not all(letters.values()):
            continue
        found = _definitions(lines, {c: str(letters[c]) for c in codes})
        if not found:
            continue
        names, line = found
        if _OFF in values:
            names[_OFF] = _OFF
        rename_codes(b, var, spec, names)
        if _OFF in values:
            spec["show"][_OFF] = ""
        b.note(
            f"variables.{var}.values",
            "codes spelt out by the manual: " + ", ".join(f"{c} {n}" for c, n in names.items()),
            unit_at(b, line),
        )


def _letter(code: str, stems: set[str]) -> str | None:
    """The letter after the setting's own name ("osc-n" of osc → "n"), or None."""
    head, dash, tail = code.partition("-")
    if dash and head in stems and re.fullmatch(r"[a-z]{1,2}", tail):
        return tail
    return None


def _definitions(lines: list[str], letters: dict[str, str]) -> tuple[dict[str, str], int] | None:
    """Lines each led by one code and its name ("OSC-N   narrow: …"), one name per code."""
    names: dict[str, str] = {}
    first = 0
    for code, letter in letters.items():
        lead = re.compile(rf"^\s*(?:[-•▪*]\s*)?{re.escape(code.upper())}(?:\s*[-–—:=]\s*|\s+)(.*)")
        for number, line in enumerate(lines, 1):
            match = lead.match(line)
            if not match:
                continue
            name = _meaning(letter, _WORD.findall(match.group(1))[:_LEAD])
            if name:
                names[code] = name
                first = first or number
                break
    if len(names) == len(letters) and len(set(names.values())) == len(letters):
        return names, first
    return None
