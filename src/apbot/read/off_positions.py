"""A knob whose positions are OFF and a run of levels: the volume knob of a radio or monitor
that is also its on/off switch.

"The VOL / OFF knob … has nine click positions: OFF and levels 1 to 8." A knob that starts at
OFF and clicks through levels switches the appliance on at its first click and off again past
the lowest level; while it stands at OFF nothing else works. The reader otherwise guesses the
knob's amount as 0–10 and knows no off state, so the loop presses keys on a dark panel. This
rule makes the one turned knob's setting the list OFF, A … B, and lets the existing guard of
a knob at OFF (only its turns work) follow.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.values import number

# "positions: OFF and levels 1 to 8", "Positions: OFF, 1 to 8.", "positions off and 1–8": the
# word OFF in any case, then a comma or "and", then a run of levels however its ends are joined
_OFF_LEVELS_RE = re.compile(
    r"\bpositions?\s*[:—–-]?\s*(?:(?:an?|the)\s+)?off\s*(?:,|\band\b)\s*(?:levels?\s+)?"
    r"(\w+)\s*(?:\bto\b|–|-)\s*(\w+)\b",
    re.I,
)
_MAX_LEVELS = 20


def read_off_positions(b: Builder) -> None:
    """Give the one variable a knob's turns step the values OFF, A … B its positions name."""
    turned = [
        (name, step)
        for name, steps in b.features.items()
        for step in steps
        if step.get("variable")
        and any(i.skill in ("turn_cw", "turn_ccw") for i in b.infos if i.name in step["actions"])
    ]
    if len({step["variable"] for _, step in turned}) != 1:
        return
    var = turned[0][1]["variable"]
    spec = b.variables[var]
    if spec.get("type") != "numeric" or spec.get("cases"):
        return
    for at, unit in enumerate(b.manual.units):
        m = _OFF_LEVELS_RE.search(unit.text)
        if m is None:
            continue
        low, high = number(m.group(1)), number(m.group(2))
        if low is None or high is None or not 0 < high - low < _MAX_LEVELS:
            continue
        for key in ("ranges", "unit", "entry", "show"):
            spec.pop(key, None)
        spec["type"] = "discrete"
        spec["values"] = ["off"] + [f"{low + k:g}" for k in range(int(high - low) + 1)]
        spec["wrap"] = False
        spec["initial"] = "off"
        cw = [i.name for i in b.infos if i.skill == "turn_cw"]
        if "power" not in b.variables and not any(g["name"] == "power off" for g in b.guards):
            b.guards.append(
                {"name": "power off", "when": {var: "off"}, "only": cw, "display": "", "hide": True}
            )
        b.note(f"variables.{var}.values", f"off, {low:g} … {high:g} (the knob's positions)", at)
        return
