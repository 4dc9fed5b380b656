"""A setting guessed on/off whose own section prints its display lines with their meaning:
"HEMI N   northern hemisphere (Europe …)" and "HEMI S   southern hemisphere (…)".

A key that flips a setting between two states (a hold of MENU, a slide switch) was read as an
on/off toggle when no sentence said "on or off"; its section shows what the display says in
each state, one line each, the display word and its code, then a gap and what it means. The
values are the meanings less the setting's own name ("northern", "southern"), shown as the
display prints them; a meaning that is only the setting's name keeps the code.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words

# a display line: a display word, a code, a gap, then what it means up to a bracket or stop
_LINE_RE = re.compile(
    r"^([A-Z]{2,10}\s[A-Z0-9]{1,6})\s{2,}([A-Za-z][A-Za-z -]{1,40}?)\s*(?:[(.,;]|$)"
)


def read_shown_pairs(b: Builder) -> None:
    """Give each guessed on/off setting the two display lines its own section prints."""
    guessed = {n.subject for n in b.notes if n.guess}
    for var, spec in b.variables.items():
        if spec.get("values") != ["off", "on"] or f"variables.{var}" not in guessed:
            continue
        own = {w for w in words(var.replace("_", " ")) if len(w) >= 4}
        if not own:
            continue
        found = _pair(b, own)
        if found is None:
            continue
        pairs, at = found
        spec["values"] = [v for v, _ in pairs]
        spec["show"] = {v: shown for v, shown in pairs}
        spec.pop("initial", None)
        b.notes = [n for n in b.notes if not (n.guess and n.subject == f"variables.{var}")]
        b.note(
            f"variables.{var}",
            "two states its section shows: " + ", ".join(f"{s} {v}" for v, s in pairs),
            at,
        )


def _pair(b: Builder, own: set[str]) -> tuple[list[tuple[str, str]], int] | None:
    """The (value, shown) of the two display lines in the section headed by the setting's
    name, one word for the display; None unless exactly two such lines stand together."""
    units = b.manual.units
    for i, unit in enumerate(units):
        if not own & set(words(unit.heading)):
            continue
        m = _LINE_RE.match(unit.text)
        if m is None or (i > 0 and _LINE_RE.match(units[i - 1].text)):
            continue
        lines = [m]
        for after in units[i + 1 : i + 4]:
            n = _LINE_RE.match(after.text)
            if n is None:
                break
            lines.append(n)
        if len(lines) != 2 or len({ln[1].split()[0] for ln in lines}) != 1:
            return None
        pairs = []
        for ln in lines:
            said = [w for w in words(ln[2]) if w not in own]
            value = " ".join(said) if 1 <= len(said) <= 2 else ln[1].split()[1].lower()
            pairs.append((value, ln[1]))
        if pairs[0][0] == pairs[1][0]:
            return None
        return pairs, i
    return None
