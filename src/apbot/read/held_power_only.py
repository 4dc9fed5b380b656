"""A power key held to switch on and off, whose short press does something else: "To switch on,
hold ⏻ for one second … A short press of ⏻ does not switch it on", "each short press of ⏻ steps
the brightness".

Lamps, torches and small handheld devices save the long press for the power (so that a bump in
a bag does not switch them on) and give the short press a setting of its own. Where the manual
says the hold switches the appliance both ways, and the short press is denied switching on or
is given a step of its own, the hold is the power toggle and the press is left for that
setting, not read as "press on, hold off".
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_holds import held_power

# "a short press of ⏻ does NOT switch the torch on", "short presses are ignored while off"
_PRESS_NOT_ON = re.compile(
    r"\bshort\s+press(?:es)?\b[^.]{0,40}?\b(?:does\s+not|doesn't|will\s+not|cannot|never)\s+"
    r"(?:switch|turn)\b",
    re.I,
)
# "each short press of ⏻ moves one step up", "a short press of ⏻ steps the output"
_PRESS_STEPS = re.compile(
    r"\b(?:each|every)\s+(?:short\s+)?press\s+of\s+(?:the\s+)?(?P<label>\S{1,12})"
    r"(?:\s+(?:key|button))?\s+(?:moves|steps|goes|raises|changes|selects)\b",
    re.I,
)


def held_press_free(b: Builder, hold: ActionInfo, press: ActionInfo) -> int | None:
    """The unit saying the hold switches the appliance on and off, where the short press of
    the same key has another job (see the module's docstring); None otherwise."""
    at = held_power(b, hold)
    if at is None or not press.controls or press.controls[0] not in b.labels:
        return None
    label = b.labels[press.controls[0]].text
    for unit in b.manual.units:
        if _PRESS_NOT_ON.search(unit.text):
            return at
        for m in _PRESS_STEPS.finditer(unit.text):
            if m.group("label").strip("(),.:") == label:
                return at
    return None


# "each short press of ⏻ moves one step up the output scale", "… steps the white output"
_STEP_NOUN = re.compile(
    r"\b(?:each|every)\s+(?:short\s+)?press\s+of\s+(?:the\s+)?(?P<label>\S{1,12})"
    r"(?:\s+(?:key|button))?\s+(?:moves|steps|goes)\s+(?:one\s+step\s+)?(?:up|on|through|along|round)?\s*"
    r"(?:the|its)\s+(?P<noun>[a-z]+(?:\s+[a-z]+)?)",
    re.I,
)
_SCALE = {"scale", "level", "levels", "settings", "setting", "steps", "list", "cycle"}


def power_key_steps(b: Builder, key: ActionInfo) -> str:
    """What the short press of the power key steps, named by the sentence that steps it ("each
    short press of ⏻ moves one step up the output scale": output); "" if no such sentence. The
    power key's own name is the power's: the setting it also steps needs a name of its own."""
    if key.skill != "press" or "power" not in b.variables or not key.controls:
        return ""
    lab = b.labels.get(key.controls[0])
    if lab is None or b.variables["power"].get("label") != lab.text:
        return ""
    for i in lab.mentions:
        for m in _STEP_NOUN.finditer(b.manual.units[i].text):
            if m.group("label").strip("(),.:") != lab.text:
                continue
            said = [w for w in m.group("noun").lower().split() if w not in _SCALE]
            if said:
                return said[-1]  # "the white output": the output
    return ""
