"""A hold named by a job that moves a number by a stated amount: "tack to port" on an autopilot.

Some holds are named for what they do (``hold_tack_port``) and their sentence says so in words
and a worked example: "to tack to PORT, hold −1 and −10 together for a second: the course
changes by 100° to port (e.g. 270° → 170°)". Read key by key such a hold was guessed a switch
of its own ("tack_port_hold" on / off), which a goal parser could set and no panel has. Read
here: a hold still guessed so, a sentence naming every word of the hold's name and holding
keys, a number setting the model has named in it ("the course"), and the example's two values
"A → B" inside that setting's range. The hold adds B − A to the setting (through its ends when it
wraps: 270° → 010° is +100 on a 0–359 course).
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.held_guesses import drop_guess
from apbot.read.held_sections import guessed_hold

_EXAMPLE_RE = re.compile(r"(?<![\d.])(\d{1,4})\s*°?\s*(?:→|->|to)\s*(\d{1,4})\s*°?(?![\d.])")


def read_held_changes(b: Builder) -> None:
    """Give each hold named by its job the change of a number its sentence states."""
    units = b.manual.units
    for info in b.infos:
        if info.skill != "hold" or len(info.controls) != 1 or not guessed_hold(b, info.name):
            continue
        named = info.controls[0].split("_")
        if len(named) < 2:
            continue
        for at, unit in enumerate(units):
            text = " ".join(u.text for u in units[at : at + 2])
            first = unit.text.lower()
            if not all(re.search(rf"\b{re.escape(w)}\b", first) for w in named):
                continue
            if not re.search(r"\bhold\b", first):
                continue
            change = _change(b, text)
            if change is None:
                continue
            var, amount = change
            drop_guess(b, info.name)
            effect: dict[str, Any] = {info.name: {"add": amount}}
            b.feature(
                f"{info.controls[0]}", [{"actions": [info.name], "variable": var, "effect": effect}]
            )
            b.note(f"features.{info.controls[0]}", f"{info.name} adds {amount} to {var}", at)
            break


def _change(b: Builder, text: str) -> tuple[str, float] | None:
    """The number setting named in the sentence and the change its example shows."""
    for var, spec in b.variables.items():
        if spec.get("type") != "numeric" or not spec.get("ranges"):
            continue
        if not re.search(rf"\b{re.escape(var.replace('_', ' '))}\b", text, re.I):
            continue
        low, high = spec["ranges"][0][0], spec["ranges"][-1][1]
        for m in _EXAMPLE_RE.finditer(text):
            a, z = float(m.group(1)), float(m.group(2))
            if not (low <= a <= high and low <= z <= high) or a == z:
                continue
            delta = z - a
            if spec.get("wrap"):
                span = high - low + spec["ranges"][0][2]
                delta = (delta + span / 2) % span - span / 2
            return var, int(delta) if float(delta).is_integer() else delta
    return None
