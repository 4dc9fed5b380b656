"""Levels named by the lamp that lights: "the 1st lamp … up to the 5th lamp".

Small controllers (blankets, heating pads, foot warmers) have no figures: a row of lamps shows
the level, and the manual names each level by its lamp's place ("the 2nd lamp", "the third
LED"). A key whose own section walks through such places steps a level 1 … N (N the highest
place named); "back to the 1st" says the steps wrap; "The 1st lamp lights" said without a press
(on switching on) is where it starts. Read key by key, such a key says nothing about values and
was guessed an on/off toggle."""

from __future__ import annotations

import re

from apbot.read.build import Builder

_WORDS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6}
_PLACE = r"(?:(?P<num>[1-9])(?:st|nd|rd|th)|(?P<word>first|second|third|fourth|fifth|sixth))"
_LAMP_RE = re.compile(
    rf"\b{_PLACE}\s+(?:heat\s+|level\s+)?(?:lamps?|LEDs?|lights?|indicators?|bars?|dots?)\b",
    re.IGNORECASE,
)
_BARE_RE = re.compile(rf"\b(?:the|to\s+the)\s+{_PLACE}\b(?!\s+(?:time|press|step))", re.I)
_WRAP_RE = re.compile(rf"\b(?:back|returns?|goes)\s+to\s+the\s+{_PLACE}\b", re.IGNORECASE)
_LIT_RE = re.compile(r"\b(?:lights?(?:\s+up)?|glows?|is\s+lit|comes?\s+on)\b", re.IGNORECASE)
_PRESS_RE = re.compile(r"\b(?:press|push|touch|tap)\w*\b", re.IGNORECASE)


def _place(m: re.Match[str]) -> int:
    return int(m.group("num")) if m.group("num") else _WORDS[m.group("word").lower()]


def _guessed(b: Builder, var: str | None) -> bool:
    """Whether the variable's range was guessed (the manual gave none)."""
    return any(n.guess and n.subject == f"variables.{var}" for n in b.notes)


def read_ordinal_lamps(b: Builder) -> None:
    """Turn a key guessed a toggle (or an amount of guessed range) into levels 1 … N when its
    section names lamps by place."""
    for steps in list(b.features.values()):
        var = steps[0].get("variable")
        if len(steps) != 1 or not (
            steps[0].get("effect") == "toggle"
            or (steps[0].get("effect") == "next" and _guessed(b, var))
        ):
            continue
        spec = b.variables.get(var or "")
        if var is None or spec is None or var == "power" or len(steps[0]["actions"]) != 1:
            continue
        key = next((i for i in b.infos if i.name == steps[0]["actions"][0]), None)
        if key is None or len(key.controls) != 1 or key.controls[0] not in b.labels:
            continue
        mentions = b.labels[key.controls[0]].mentions
        heads = {b.manual.units[i].heading for i in mentions if b.manual.units[i].heading}
        section = [i for i, u in enumerate(b.manual.units) if u.heading in heads] or sorted(
            {j for i in mentions for j in range(max(0, i - 2), i + 3)}
            & set(range(len(b.manual.units)))
        )  # (no headings kept: the lines around its mentions)
        places: set[int] = set()
        lamp_at = None
        for i in section:
            found = {_place(m) for m in _LAMP_RE.finditer(b.manual.units[i].text)}
            if found:
                lamp_at = lamp_at if lamp_at is not None else i
                places |= found | {_place(m) for m in _BARE_RE.finditer(b.manual.units[i].text)}
        if len(places) < 3 or lamp_at is None or min(places) != 1:
            continue
        top = max(places)
        spec.clear()
        spec.update({"type": "numeric", "label": b.labels[key.controls[0]].text})
        spec["ranges"] = [[1, top, 1]]
        wraps = any(_WRAP_RE.search(b.manual.units[i].text) for i in section)
        spec["wrap"] = wraps
        steps[0]["effect"] = "next"
        b.note(f"variables.{var}", f"levels 1–{top}, named by the lamp that lights", lamp_at)
        for i in section:
            text = b.manual.units[i].text
            lit = _LAMP_RE.search(text)
            if lit and _LIT_RE.search(text) and not _PRESS_RE.search(text):
                spec["initial"] = _place(lit)
                b.note(f"variables.{var}.initial", f"starts at {_place(lit)}", i)
                break
