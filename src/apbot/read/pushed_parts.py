"""The on/off setting a knob's push switches, from the push part of its legend line: "TEMP
turn: set point; push: heating on / off", "VOLUME  Turn: loudness · Push: mute on / off".

A push-and-turn knob's legend gives a use per way of touching it. When the push part names a
thing switched on and off, the push is a toggle of that thing (the user asks for "the heating
on"), not the first step of setting the knob's amount nor a start key; the knob's turns keep
setting its own amount. The holding twin of this reading is held_parts.py.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.legend_rest import legend_rests
from apbot.read.roles_holdcell import lock_or_appliance, names_a_setting

# the part of a legend line kept for pushing, then the thing it switches on and off
_PUSH_PART = re.compile(
    r"^(?:push|pushed|pushing|press|pressed|pressing)(?:\s+(?:it|once|briefly))?"
    r"\s*(?::\s*|\s+to\s+(?:switch|turn)\s+)(?:the\s+)?"
    r"(?P<noun>[a-z][a-z -]{1,30}?)\s+(?:on\s*(?:/|or)\s*off|off\s*(?:/|or)\s*on)\b",
    re.IGNORECASE,
)
_TURN_PART = re.compile(r"^(?:turn|turned|turning|rotate|rotated)\b", re.IGNORECASE)
_PARTS = re.compile(r"[.;·]\s+|\s{3,}|\s+[·|]\s*")
# a lamp's legend: "HEAT: heating is on", "STIR  the stirring motor is on"
_LAMP_HEAD = r"(?<![\w/])([A-Z][A-Z0-9]{1,11})(?::\s*|\s{2,}|\s+[-–—]\s+)(?:the\s+)?"
_LAMP_TAIL = r"\w*\b[^.;|]{0,20}\bis\s+on\b"


def pushed_part_toggle(b: Builder, key: ActionInfo) -> str:
    """What pushing the knob ``key`` presses switches on and off, said in the push part of a
    legend line that also says what turning it does; ""."""
    if key.skill != "press" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return ""
    label = b.labels[key.controls[0]].text
    for _, rest in legend_rests(b, key.controls[0]):
        parts = [p.strip() for p in _PARTS.split(rest)]
        if not any(_TURN_PART.match(p) for p in parts):
            continue  # (a legend of a knob's two ways of touching: turn, then push)
        for part in parts:
            said = _PUSH_PART.match(part)
            if not said:
                continue
            noun = said.group("noun").strip(" -").lower()
            if set(words(noun)) <= set(words(label)):
                return ""  # the knob's own name: no setting of another name
            if not lock_or_appliance(noun) and names_a_setting(noun):
                return noun
    return ""


def pushed_toggle(b: Builder, key: ActionInfo, noun: str) -> str:
    """The toggle ``key`` switches, shown by the lamp whose legend says the noun is on."""
    name = "_".join(words(noun))
    stem = re.escape(words(noun)[0][:4])
    lamp = re.compile(_LAMP_HEAD + stem + _LAMP_TAIL)
    shown = next(
        ((m.group(1), i) for i, u in enumerate(b.manual.units) if (m := lamp.search(u.text))),
        None,
    )
    var = b.add_toggle(name, shown[0] if shown else noun.upper(), None)
    if shown is not None and "show" not in b.variables[var]:
        b.variables[var]["show"] = {"off": "", "on": shown[0]}
        b.note(f"variables.{var}.show", f"the {shown[0]} lamp is lit while on", shown[1])
    b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])
    b.note(f"features.{var}", f"{key.name} switches the {noun} on and off (its push part)")
    return var
