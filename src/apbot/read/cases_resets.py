"""Programmes that reset settings: "choosing a programme loads its defaults".

Split out of ``cases.py``: a sentence, not a table, says the programme's steps reset the
other settings, so it is read on its own after the programme tables.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.shapes import CHOICE_WORDS

STAY_RE = re.compile(
    r"\b(?:stays?|remains?|kept|keeps?|unchanged|not (?:reset|lost|changed?|cleared))\b", re.I
)
RESET_NOUN_RE = re.compile(
    r"\b(?:programmes?|programs?|menus?|modes?|presets?|functions?|cycles?|courses?)\b", re.I
)
RESET_RE = re.compile(
    r"\b(?:programmes?|programs?|menus?|modes?|presets?|functions?|cycles?|courses?|selector)\b"
    r"[^.]*\b(?:defaults?|standard values|reset|go(?:es)? back|return|wipes?|clear|lost|forget)"
    r"|\b(?:defaults?|reset|go(?:es)? back|return|wipes?|clear|lost)\b[^.]*"
    r"\b(?:programmes?|programs?|menus?|modes?|presets?|functions?|cycles?|courses?)\b",
    re.IGNORECASE,
)


def apply_resets(b: Builder) -> None:
    """ "Choosing a programme loads its defaults": the programme's steps reset the settings."""
    units = b.manual.units
    at = next(
        (i for i, u in enumerate(units) if RESET_RE.search(u.text) and not STAY_RE.search(u.text)),
        None,
    )
    if at is None:
        return
    kept = {  # "your taste choice stays the same when you change the mode"
        n
        for u in units
        if STAY_RE.search(u.text) and RESET_NOUN_RE.search(u.text)
        for n in b.variables
        if set(words(n.replace("_", " "))) & set(words(u.text))
    }
    fixed = {v for g in b.guards for v in g["when"]}
    parents = {s.get("depends_on") for s in b.variables.values()} - {None}
    choices = [
        n
        for n, s in b.variables.items()
        if s.get("type") == "discrete"
        and n not in fixed
        and (n in parents or set(words(n.replace("_", " "))) & CHOICE_WORDS)
    ]
    if not choices:
        return
    choice = choices[0]
    others = [
        n
        for n, s in b.variables.items()
        if n != choice
        and n not in fixed
        and n not in kept
        and s.get("depends_on") is None
        and n != "running"
    ]
    if not others:
        return
    for steps in b.features.values():
        for step in steps:
            if step.get("variable") == choice:
                step["reset"] = [n for n in others if n != step.get("variable")]
    b.note(f"variables.{choice}", f"choosing it resets {', '.join(others)}", at)
