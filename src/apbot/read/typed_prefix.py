"""The letter a display prints before a number typed on the keypad: "1 2 shows d12", "the
panel shows d1 (design 1)".

A small display often marks what a number is with a letter in front of it (d for a design, P
for a programme, C for a channel). A manual shows it by example: the digits typed and what the
display then shows, or the display's text with the number it stands for in brackets. A keyed
number whose examples all carry the same letter is shown as that letter and the number; without
this the agent cannot read "d12" as twelve and blames the wrong key.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words

# "1 2 shows d12", "1 2 0 gives d120": typed digits, then the display with a letter before them
_TYPED_SHOWN_RE = re.compile(
    r"(?<![\w.])(\d(?:\s+\d){0,3})\s+(?:shows?|gives?|displays?)\s+([A-Za-z]{1,2})(\d{1,4})\b"
)
# "shows d1 (design 1)": the display's text, then the number it is in words of the setting
_GLOSSED_RE = re.compile(r"(?<![\w.])([A-Za-z]{1,2})(\d{1,4})\s*\(\s*([a-z]{3,})\s+(\d{1,4})\s*\)")


def read_typed_prefixes(b: Builder) -> None:
    """Give a number typed on the keypad the letter its display examples print before it."""
    for var, spec in b.variables.items():
        entry = spec.get("entry") or {}
        if spec.get("type") != "numeric" or entry.get("format") != "number" or "show" in spec:
            continue
        own = {w[:5] for w in [*words(var.replace("_", " ")), *words(str(spec.get("label", "")))]}
        letters: dict[str, int] = {}
        for i, unit in enumerate(b.manual.units):
            for m in _TYPED_SHOWN_RE.finditer(unit.text):
                if "".join(m.group(1).split()) == m.group(3):
                    letters.setdefault(m.group(2), i)
            for m in _GLOSSED_RE.finditer(unit.text):
                if m.group(2) == m.group(4) and m.group(3)[:5] in own:
                    letters.setdefault(m.group(1), i)
        if len(letters) != 1:
            continue  # no example, or examples that disagree: leave the display to the agent
        letter, at = next(iter(letters.items()))
        spec["show"] = f"{letter}{{value}}"
        b.note(f"variables.{var}.show", f"shown as {letter} and the number", at)
