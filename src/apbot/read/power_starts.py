"""A power key that starts the work itself: "put the brush in your mouth, then press ⏻. The
brush starts …", "To stop earlier, press ⏻".

Small appliances without a START key (a toothbrush, a shaver, a hand blender) often have one
⏻ key that starts and stops the work; there is no state of being on and idle. Read as a power
switch, the belief guards every other key while "off" — the opposite of the truth, where the
keys work while it is stopped and some are refused while it runs. Such a key is the appliance's
start/stop instead: a running state, no power guard.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.shapes import STOP_WORDS

# ("The detector always starts in ALL METAL mode": the state it comes on in, no work begun;
# "the brush starts in the mode shown" does begin the work)
_STARTS_RE = re.compile(
    r"\b(?:starts|begins|starts running|runs)\b(?!\s+(?:in|at|with|from)\s+(?-i:[A-Z0-9]))",
    re.IGNORECASE,
)
_SWITCHED_ON_RE = re.compile(
    r"\b(?:switch(?:es|ed)?|turn(?:s|ed)?)\s+(?:it\s+|the\s+(?:[\w-]+\s+){1,3})?on\b"
    r"|\bswitch(?:es)?\s+on\b|\bpower(?:s|ed)?\s+(?:it\s+)?(?:on|up)\b",
    re.IGNORECASE,
)
# "SPEED and OSC work only while the fan is running": the other keys wait for the power, as a
# power switch's guard says; a start/stop key leaves them free while stopped
_ONLY_WHILE_ON_RE = re.compile(
    r"\bonly\s+(?:while|when|if|once)\s+(?:the\s+)?(?:[\w-]+\s+){0,3}(?:is\s+)?"
    r"(?:running|on|switched\s+on|turned\s+on|operating|working)\b",
    re.IGNORECASE,
)


def power_starts_work(b: Builder, info: ActionInfo) -> bool:
    """Whether the (pressed) power key starts the work: a sentence presses it and it or the
    next one says the appliance starts, no sentence has it switch the appliance on, and no
    other key starts or stops anything."""
    if info.skill != "press" or len(info.controls) != 1 or info.controls[0] not in b.labels:
        return False
    if not _power_key(info.token, b.labels[info.controls[0]].text):
        return False
    if any(
        "start" in words(i.token) or set(words(i.token)) & STOP_WORDS
        for i in b.infos
        if i.token != info.token
    ):
        return False
    label = b.labels[info.controls[0]]
    if not label.text:
        return False
    units = b.manual.units
    if any(_ONLY_WHILE_ON_RE.search(u.text) for u in units):
        return False
    pressed = re.compile(rf"\bpress\s+(?:the\s+)?{re.escape(label.text)}(?!\w)", re.IGNORECASE)
    starts = False
    for i in label.mentions:
        after = units[i + 1].text if i + 1 < len(units) else ""
        if _SWITCHED_ON_RE.search(units[i].text) or _SWITCHED_ON_RE.search(after):
            return False  # "ON/OFF — … Switches the cooker on and off": a power switch
        if not pressed.search(units[i].text):
            continue
        if _STARTS_RE.search(units[i].text) or _STARTS_RE.search(after):
            starts = True
    return starts


def _power_key(token: str, label: str) -> bool:
    """Whether the key is the power key by its action name or its printing (⏻, ON/OFF, I/O)."""
    squashed = "".join(words(label))
    return (
        token in ("power", "on_off", "onoff", "power_on_off")
        or label.strip() == "⏻"
        or squashed in ("onoff", "io", "power")
    )
