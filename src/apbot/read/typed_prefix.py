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


# "9 0 0 0 shows 90:00": typed digits, then the time as the display shows it ("4 5 gives 0:45"
# tells the value, not what the display prints around it)
_TYPED_CLOCK_RE = re.compile(
    r"(?<![\w.:])(\d(?:\s+\d){0,5})\s+(?:shows?|displays?)\s+(\d{1,2}:\d{2}(?::\d{2})?)(?![\w:])"
)


def _typed_clocks(b: Builder) -> None:
    """A time typed on the keypad whose examples show the digits as a bare clock ("4 5 gives
    00:45"): the display prints the time alone, no name before it. Only the one time the keypad
    types (with several, an example tells nothing of the others)."""
    keyed = [
        var
        for var, spec in b.variables.items()
        if spec.get("type") == "time" and ":" in str((spec.get("entry") or {}).get("format", ""))
    ]
    for var in keyed if len(keyed) == 1 else []:
        spec = b.variables[var]
        if "show" in spec:
            continue
        for i, unit in enumerate(b.manual.units):
            for m in _TYPED_CLOCK_RE.finditer(unit.text):
                typed, shown = "".join(m.group(1).split()), m.group(2).replace(":", "")
                if shown.endswith(typed[-len(shown) :]):  # (a fifth digit pushed one out)
                    spec["show"] = "{value}"
                    b.note(f"variables.{var}.show", "shown as the time alone (typed examples)", i)
                    break
            if "show" in spec:
                break


def read_typed_prefixes(b: Builder) -> None:
    """Give a number typed on the keypad the letter its display examples print before it (and
    a typed time the bare clock its examples show)."""
    _typed_clocks(b)
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
