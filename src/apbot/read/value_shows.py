"""What the display shows for each value, said in brackets after the value in a list: "OFF → ON
(steady, the display shows LIGHT) → FLASH (warning flash, the display shows FLASH)".

A manual walking through a key's states often adds, for each, the word the display then prints.
That word is the value's display text; "off" with no word of its own shows nothing. Without it
the agent reads such a setting as unreadable (the display prints LIGHT, not ON).
"""

from __future__ import annotations

import re

from apbot.read.build import Builder

_SHOWS_RE = re.compile(
    r"\b(?:display|screen)\s+(?:shows|reads|displays)\s+([A-Z][A-Z0-9+-]{1,11})(?![\w])"
)


def read_bracket_shows(b: Builder) -> None:
    """Give a discrete setting read without display words the words its list's brackets say
    the display shows for two or more of its values (the others: off shows nothing)."""
    # only a sentence saying what the display shows can give a bracket's word
    said_shown = [
        (i, u.text)
        for i, u in enumerate(b.manual.units)
        if "(" in u.text and _SHOWS_RE.search(u.text)
    ]
    if not said_shown:
        return
    for var, spec in b.variables.items():
        if spec.get("type") != "discrete" or "show" in spec or spec.get("cases"):
            continue
        values = [str(v) for v in spec.get("values", [])]
        for i, text in said_shown:
            shown: dict[str, str] = {}
            for value in values:
                pattern = rf"(?<![\w]){re.escape(value)}\s*\(([^()]*)\)"
                for m in re.finditer(pattern, text, re.IGNORECASE):
                    said = _SHOWS_RE.search(m.group(1))
                    if said:
                        shown.setdefault(value, said.group(1))
            if len(shown) < 2 or any(v not in shown and v != "off" for v in values):
                continue
            spec["show"] = {v: shown.get(v, "") for v in values}
            b.note(f"variables.{var}.show", "the display word each value's bracket gives", i)
            break
