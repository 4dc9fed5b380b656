"""The keys a walk is stepped with: the stepping pairs the model already has, the pair a step
names, and the short press of the walk's own key that moves on to the next field.

Both walk readers (a hold opening the walk, ``held_walks``; a short press, ``pressed_walks``)
recognise their steps by these keys, so they share one reading of them.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.held_guesses import says
from apbot.read.walk_like import squeezed_arrows
from apbot.read.walk_steps import adjusts

# a dial named by its kind rather than its label: "Turn the knob to choose …"
_TURN_RE = re.compile(r"\bturn\s+the\s+(?:\w+\s+)?(?:knob|dial|wheel|ring|selector)\b", re.I)


def stepping_pairs(b: Builder) -> list[tuple[list[str], list[str]]]:
    """The stepping pairs the model already has: presses (or a dial's two turns) that step one
    setting up and down."""
    press = {i.name for i in b.infos if i.skill == "press" or i.skill.startswith("turn")}
    out: list[tuple[list[str], list[str]]] = []
    for steps in b.features.values():
        for step in steps:
            effect = step.get("effect")
            if not isinstance(effect, dict):
                continue
            up = [a for a, e in effect.items() if e == "next" and a in press]
            # (or the hold of the up key's own control: "next size (press) / previous (hold)")
            own = {controls_of(b, a) for a in up}
            down = [
                a
                for a, e in effect.items()
                if e == "prev" and (a in press or (len(up) == 1 and controls_of(b, a) in own))
            ]
            if up and down and (up, down) not in out:
                out.append((up, down))
    return out


def moves_on(text: str, label: str) -> bool:
    """A step that is a short press of the walk's key ("Press CLOCK briefly.")."""
    return (
        re.match(rf"^(?:press|touch)\s+{re.escape(label)}(?!\w)(?!\s+and\b)", text, re.I)
        is not None
    )


def pair_of(
    b: Builder, pairs: list[tuple[list[str], list[str]]], text: str
) -> tuple[list[str], list[str]] | None:
    """The stepping pair a step names with both its keys ("Press ▲ or ▼ to …")."""
    text = squeezed_arrows(text)  # "A ▲ / A ▼" for the keys labelled A▲ and A▼
    for up, down in pairs:
        ups = [b.labels[t].text for a in up for t in controls_of(b, a) if t in b.labels]
        downs = [b.labels[t].text for a in down for t in controls_of(b, a) if t in b.labels]
        if any(says(text, x) for x in ups) and any(says(text, x) for x in downs):
            return up, down
        if not down and any(adjusts(text, x) for x in ups):  # "Press MEM until … is right"
            return up, down
    dials = [p for p in pairs if all(_turned(b, a) for a in p[0] + p[1])]
    if len(dials) == 1 and _TURN_RE.search(text):  # "Turn the knob to choose …"
        return dials[0]
    return None


def _turned(b: Builder, action: str) -> bool:
    """Whether the action turns a dial: the one dial is the pair a step says only "turn" for."""
    return any(i.name == action and i.skill.startswith("turn") for i in b.infos)


def controls_of(b: Builder, action: str) -> tuple[str, ...]:
    """The panel controls an action works, as grounding named them (none if it is unknown)."""
    return next((i.controls for i in b.infos if i.name == action), ())
