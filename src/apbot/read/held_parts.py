"""The on/off setting a held key switches, from the part of its legend kept for holding: "FOOD
Touch: DRY <-> MOIST.  Touch and hold 3 seconds: double seal on / off", "(c) ALERT  short: the
alert limit · held 2 s: alert on / off", "LIGHT - backlight on / off; hold 2 seconds for auto
scan on / off".

A legend line gives one key a use per way of touching it, the parts split by a full stop, a
semicolon, a middle dot or a wide gap. The part that starts with the hold says what holding
switches; the setting is named by those words ("double seal"), never by the gesture
("food_hold") nor with the "on" of "on / off" ("double_seal_on"), since the user asks for the
double seal. The key lock and the appliance itself are jobs, not settings, and give no name.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.legend_rest import legend_rests
from apbot.read.roles_holdcell import lock_or_appliance, names_a_setting

_SECONDS = r"(?:for\s+)?(?:about\s+)?\d+(?:[.,]\d+)?\s*(?:s|sec|secs|seconds?)\b"
# the part of a legend line kept for holding, then the thing it switches on and off
_HOLD_PART = re.compile(
    rf"^(?:(?:touch|press|push|tap)\s+(?:and|&)\s+)?(?:hold|held|holding)(?:\s+(?:it|down))?"
    rf"\s*(?:{_SECONDS})?\s*(?::\s*|\s+for\s+|\s+to\s+(?:switch|turn)\s+)(?:the\s+)?"
    r"(?P<noun>[a-z][a-z -]{1,30}?)(?:\s+mode)?\s+(?:on\s*(?:/|or)\s*off|off\s*(?:/|or)\s*on)\b",
    re.IGNORECASE,
)
# where a legend line's uses part: a full stop, a semicolon, a middle dot, a wide gap
_PARTS = re.compile(r"[.;·]\s+|\s{3,}|\s+[·|]\s*")


def held_part_toggle(b: Builder, key: ActionInfo) -> str:
    """What holding ``key`` switches on and off, said in a part of its own legend line; ""."""
    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return ""
    label = b.labels[key.controls[0]].text
    for _, rest in legend_rests(b, key.controls[0]):
        for part in _PARTS.split(rest):
            said = _HOLD_PART.match(part.strip())
            if not said:
                continue
            noun = said.group("noun").strip(" -").lower()
            if set(words(noun)) <= set(words(label)):
                return ""  # "ALERT … held 2 s: alert on / off": the key's own name, no new one
            if not lock_or_appliance(noun) and names_a_setting(noun):
                return noun
    return ""
