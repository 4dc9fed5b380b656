"""A value printed as one letter or a sign, named by the word the manual glosses it with.

"45MIN, 60MIN or C for continuous", "C means continuous", "With ∞ (continuous) it runs until
you press STOP": the user says "continuous", the display prints C or ∞. The value takes the
word as its name and keeps the letter or sign as what the display shows. Apart from
code_glosses.py, which names display *words* by a gloss holding the word itself; a letter or a
sign shares no word with its gloss, so only the tight shapes count here ("X for W", "X means
W", "X stands for W", "X = W", "X (W)"), one word of four letters or more."""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.codes import rename_codes

_SIGN = re.compile(r"[A-Za-z]|[^\w\s]")  # one letter, or one sign (∞, ☼)
_STOP = frozenset({"example", "instance", "short", "each", "every", "this", "that", "more"})


def _printed(value: str) -> str:
    return value.upper() if value.isalpha() else value


def _gloss(text: str, printed: str) -> str | None:
    sign = re.escape(printed)
    for pattern in (
        rf"(?<![\w/]){sign}\s+(?:for|means|stands\s+for|=)\s+([a-z]{{4,}})\b",
        rf"(?<![\w/]){sign}\s*\(([a-z]{{4,}})\)",
        # a heading's sign and two words, the first its name: "M (manual flash)" (set27a)
        rf"^\s*{sign}\s*\(([a-z]{{4,}})\s+[a-z]{{3,}}\)",
    ):
        m = re.search(pattern, text)
        if m and m.group(1) not in _STOP:
            return m.group(1)
    return None


def _values(spec: dict[str, Any]) -> list[str]:
    """A choice's values, or every programme's in turn when they depend on one."""
    out = [str(v) for v in spec.get("values") or []]
    for case in (spec.get("cases") or {}).values():
        out += [str(v) for v in case.get("values") or [] if str(v) not in out]
    return out


def read_sign_glosses(b: Builder) -> None:
    """Name each one-letter or sign value of a choice by the word the manual glosses it with."""
    for var, spec in b.variables.items():
        values = _values(spec)
        if spec.get("type") != "discrete" or not 2 <= len(values) <= 12 or spec.get("show"):
            continue
        names: dict[str, str] = {}
        at = None
        for value in values:
            if not _SIGN.fullmatch(value):
                continue
            for i, unit in enumerate(b.manual.units):
                word = _gloss(unit.text, _printed(value))
                if word is not None and word not in values and word not in ("on", "off"):
                    names[value], at = word, at if at is not None else i
                    break
        if not names or len(set(names.values())) != len(names):
            continue
        renamed = {v: names.get(v, v) for v in values}
        if "cases" in spec:  # (per programme: each programme's list renamed alike)
            for case in spec["cases"].values():
                case["values"] = [renamed.get(str(v), v) for v in case.get("values") or []]
                if case.get("initial") is not None:
                    case["initial"] = renamed.get(str(case["initial"]), case["initial"])
            spec["show"] = {n: _printed(c) for c, n in renamed.items()}
        else:
            rename_codes(b, var, spec, renamed)
        b.note(
            f"variables.{var}.values",
            "a sign glossed by the manual: "
            + ", ".join(f"{_printed(c)} {n}" for c, n in names.items()),
            at,
        )
