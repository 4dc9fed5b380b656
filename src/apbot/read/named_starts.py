"""A choice's start value said right after its own name in a list of start settings.

"New radios start on CH 01, privacy code 0, call tone 1, VOX off, roger beep on": the first
figure after "start on" is the channel's; VOX's start is the value printed right after VOX.
Apart from build_base.py because finding a value beside a name is a job of its own."""

from __future__ import annotations

import re


def start_after_name(text: str, label: str, values: list[str]) -> str | None:
    """The one value of ``values`` written right after ``label`` in ``text`` ("VOX off"), or
    None when the label is not followed by one."""
    if not label or len(label) < 2:
        return None
    found = {
        v
        for v in values
        if re.search(rf"(?<!\w){re.escape(label)}\s+{re.escape(v)}(?!\w)", text, re.I)
    }
    return found.pop() if len(found) == 1 else None
