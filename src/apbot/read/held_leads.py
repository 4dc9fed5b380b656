"""A hold named by the item that leads with it: "Reverse: hold START/STOP for 2 seconds. The
REV lamp lights".

Manuals list a key's second job as an item led by the job's name and a colon, then the hold,
and say the job is on by a lamp or sign that lights. Holding a start key is otherwise guessed to
stop the programme; said so, the hold switches a setting of its own named by the lead (settings31).
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_holdcell import lock_or_appliance
from apbot.read.roles_holds import held_label

# a lamp or sign that comes on: "The REV lamp lights", "the TWIN symbol appears"
_LIT = re.compile(
    r"\b(?:lamp|light|symbol|icon|indicator|LED|sign)\b[^.;]{0,20}?\b(?:lights|appears|comes on|"
    r"is lit|glows)\b|\b[A-Z]{2,}\b[^.;]{0,10}?\b(?:lights|appears)\b"
)
# the sign's printed word: "The REV lamp lights" (REV)
_SIGN = re.compile(
    r"\b(?P<sign>[A-Z][A-Z0-9]+)\s+(?:lamp|symbol|icon|indicator|sign)?\s*(?:lights|appears)\b"
)
# leads that name no setting: advice, a heading of prose, a way of working ("Switching off:")
_NOT_A_NAME = frozenset(
    {"tip", "note", "notes", "hint", "example", "caution", "warning", "important", "attention"}
)


def held_lead(b: Builder, info: ActionInfo) -> tuple[str, int, str] | None:
    """The setting named by the lead of the sentence that holds this key, when that sentence or
    the next of its section says a lamp or sign lights; (name, unit, the sign's printed word or
    "") or None."""
    label = held_label(b, info)
    if label is None:
        return None
    led = re.compile(
        rf"^\W*(?P<lead>[A-Z][a-z]+(?:[ -][a-z]+){{0,2}})\s*:\s*(?:(?:press|touch|push)\s+and\s+)?"
        rf"hold(?:\s+down)?\s+(?:the\s+)?{re.escape(label)}(?!\w)"
    )
    units = b.manual.units
    for i in b.labels[info.controls[0]].mentions:
        m = led.match(units[i].text)
        if m is None or units[i].cells:
            continue
        lead = m.group("lead")
        first = lead.split()[0].split("-")[0].lower()
        if first in _NOT_A_NAME or first.endswith("ing") or lock_or_appliance(lead):
            continue  # "Tip: hold …", "Switching off: hold …", "Child lock: hold …"
        after = [units[i].text[m.end() :]]
        if i + 1 < len(units) and units[i + 1].heading == units[i].heading:
            after.append(units[i + 1].text)
        lit = next((text for text in after if _LIT.search(text)), None)
        if lit is not None:
            sign = _SIGN.search(lit)
            return lead, i, sign.group("sign") if sign else ""
    return None


def add_held_lead(b: Builder, info: ActionInfo, found: tuple[str, int, str], running: str) -> str:
    """The hold's toggle, shown by its sign while on; the sign is no longer the run's (a sign
    lit by the hold's sentence is the hold's, not the programme's running)."""
    name, at, sign = found
    var = b.add_toggle("_".join(re.findall(r"[a-z0-9]+", name.lower())), name, at)
    if sign:
        b.variables[var]["show"] = {"off": "", "on": sign}
        b.note(f"variables.{var}.show", f"the {sign} lamp is lit while on", at)
        shown = b.variables.get(running, {}).get("show") or {}
        if shown.get("on") == sign:
            b.variables[running].pop("show")
    b.feature(var, [{"actions": [info.name], "variable": var, "effect": "toggle"}])
    return var
