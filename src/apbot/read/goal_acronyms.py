"""A panel's initials said as the words they stand for: "the voltage reduction" for VRD.

Manuals spell out a key's or a lamp's initials once, in brackets either way round ("VRD
(VOLTAGE REDUCTION DEVICE)", "Automatic Voltage Regulation (AVR)"); a user says the words, the
model names the setting by the initials. Where the bracketed words' first letters spell the
initials exactly, the words said (all of them, or all but a last one of three or more: "the
voltage reduction") are written as the initials before the instruction is read.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from apbot.read.goal_view import Model

_SMALL = frozenset({"of", "and", "the", "for", "a", "to", "&"})
_WORDS = r"[a-z][a-z]*(?:[ -]+[a-z]+){1,5}"


def _initials(model: Model) -> set[str]:
    """Names of two to five letters the model gives a setting, a value or a key."""
    texts: list[str] = []
    for name, info in model.infos.items():
        texts += [name, info.var.label or ""]
        texts += [str(v) for v in info.values]
        if isinstance(info.var.show, dict):
            texts += [str(t) for t in info.var.show.values()]
    texts += [c.label or "" for c in model.model.controls]
    return {w for t in texts for w in re.findall(r"[a-z]+", t.casefold()) if 2 <= len(w) <= 5}


def _spelled(initials: str, words: str) -> bool:
    first = [w[0] for w in re.split(r"[ -]+", words) if w and w not in _SMALL]
    return "".join(first) == initials


def _expansions(model: Model) -> Iterable[tuple[str, str]]:
    """(initials, the words they stand for) as the manual brackets them."""
    wanted = _initials(model)
    for line in model.manual_lines:
        for match in re.finditer(rf"\b([a-z]{{2,5}})\s*\(({_WORDS})\)", line):
            if match[1] in wanted and _spelled(match[1], match[2]):
                yield match[1], match[2]
        for match in re.finditer(rf"\b({_WORDS})\s*\(([a-z]{{2,5}})\)", line):
            words = match[1].split()[-len(match[2]) :]  # the words right before the bracket
            if match[2] in wanted and _spelled(match[2], " ".join(words)):
                yield match[2], " ".join(words)


def said_acronyms(view: Model, instruction: str) -> str:
    """ "turn on the voltage reduction" as "turn on the VRD" where the manual spells VRD out."""
    if not view.manual_lines:
        return instruction
    for initials, words in sorted(set(_expansions(view))):
        parts = [w for w in re.split(r"[ -]+", words) if w]
        forms = [parts] + ([parts[:-1]] if len(parts) >= 3 else [])
        for form in forms:
            pattern = r"\b" + r"[\s-]+".join(re.escape(w) for w in form) + r"\b"
            instruction = re.sub(pattern, initials.upper(), instruction, flags=re.IGNORECASE)
    return instruction
