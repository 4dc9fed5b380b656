"""What holding a key switches, read from a quick-reference row: "| red light on / off | hold
MODE 2 s |".

A quick-reference card lists what the user wants in one column ("I want to…", "To…") and what
to do in the other ("Do this"). A row whose task is a thing switched on / off and whose action is
only holding one key names the setting that hold switches, a toggle of its own, however the
key's short press is used (the press's list is not the hold's).
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder

# the action cell: hold one key, for how long at most ("hold MODE 2 s", "hold SET for 3 seconds")
_SECONDS = r"(?:\s+(?:for\s+)?(?:about\s+)?\d+(?:[.,]\d+)?\s*(?:s|sec|secs|seconds?)\b)?"


def held_task_row(b: Builder, key: ActionInfo, cell_re: re.Pattern[str]) -> str:
    """The on/off thing a quick-reference row switches by holding this key alone; "" if none.
    ``cell_re`` matches a cell naming the thing ("red light on / off", the noun as ``noun``)."""
    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return ""
    label = b.labels[key.controls[0]].text
    if not label:
        return ""
    held = re.compile(
        rf"^\W*(?:press\s+and\s+)?hold\s+(?:the\s+)?{re.escape(label)}(?!\w)(?:\s+(?:key|button))?"
        rf"{_SECONDS}\W*$",
        re.IGNORECASE,
    )
    for i in b.labels[key.controls[0]].mentions:
        cells = b.manual.units[i].cells
        if len(cells) != 2 or not held.match(cells[1]):
            continue
        m = cell_re.match(cells[0])
        if m:
            return m.group("noun").strip(" -").lower()
    return ""
