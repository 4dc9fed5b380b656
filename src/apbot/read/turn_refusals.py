"""One way of a dial refused while the appliance stands still: "Finer positions are accepted
only while the motor runs", "refuses a finer position while the motor is stopped: the screen
shows RUN FIRST".

A dial whose two turns are named by what they do (``actions._compared_dials``) may work one
way at any time and the other only while running. Without the guard a belief plans the
refused turn on a stopped appliance and keeps failing there; with it the planner starts, turns
and stops again when the goal wants the appliance not running. The sentence names the turn by
its word and says "only while … runs" or "refused … while … stopped"; the refusal's word is
what the same sentence says the screen shows, or the first cell of a table row saying the word
is refused ("RUN FIRST | finer position refused, stones stopped").
"""

from __future__ import annotations

import re

from apbot.read.actions import COMPARED
from apbot.read.build import Builder

_WORDS = {w for pair in COMPARED for w in pair}
_ONLY_RUNNING = r"only\s+(?:while|when)\s+the\s+[a-z]+\s+(?:runs?|turns?|is\s+running)"
_STOPPED = r"while\s+the\s+[a-z]+\s+(?:is\s+stopped|stands?\s+still)"
_SHOWS = re.compile(r"\bshows?\s+([A-Z][A-Z0-9-]+(?:\s[A-Z][A-Z0-9-]+)?)\b")


def _refusal_word(b: Builder, word: str, text: str) -> str:
    """What the screen shows when the turn is refused: said in the sentence, else a table row."""
    said = _SHOWS.search(text)
    if said:
        return said.group(1)
    for unit in b.manual.units:
        cells = unit.cells
        if (
            len(cells) >= 2
            and re.fullmatch(r"[A-Z][A-Z0-9 -]{1,15}", cells[0].strip())
            and re.search(rf"\b{word}\b[^|]*\brefused\b", cells[1], re.IGNORECASE)
        ):
            return cells[0].strip()
    return ""


def read_turn_refusals(b: Builder) -> None:
    """Guard a dial's turn the manual says works only while the appliance runs."""
    if "running" not in b.variables or any(g.get("when") == {"running": "off"} for g in b.guards):
        return
    for info in b.infos:
        if not info.skill.startswith("turn"):
            continue
        word = next((w for w in info.name.split("_") if w in _WORDS), None)
        if word is None:
            continue
        # (one clause: "warmer to raise the heat; the element glows only while the fan runs"
        # says when the element glows, not when the turn works)
        said = re.compile(
            rf"\b{word}\b[^.;:]{{0,60}}?\b{_ONLY_RUNNING}"
            rf"|\brefuse[sd]?\s+(?:an?|the)\s+{word}\b[^.;:]{{0,60}}?\b{_STOPPED}",
            re.IGNORECASE,
        )
        for at, unit in enumerate(b.manual.units):
            m = said.search(unit.text)
            if m is None:
                continue
            refusal = _refusal_word(b, word, unit.text[m.start() :])
            b.guards.append(
                {
                    "name": f"{word} only while running",
                    "when": {"running": "off"},
                    "only": [i.name for i in b.infos if i.name != info.name],
                    "display": refusal,
                }
            )
            b.note(f"guards.{word} only while running", f"{info.name} works only while running", at)
            return
