"""A short time typed on the number keys as a plain count of seconds ("Type the new delay in
seconds with two digits, e.g. 4 then 5 for 45 seconds"): the digits are the number, not
minutes and seconds, so the setting is a number of seconds."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import parse_hms
from apbot.read.labels import words
from apbot.read.text import Manual

# "type the delay in seconds", "enter the rinse time in seconds", "key in the seconds"
_TYPED_IN_SECONDS_RE = re.compile(
    r"\b(?:type|enter|key in|input)\b[^.;]{0,40}?\bin seconds\b", re.IGNORECASE
)


def typed_as_seconds(manual: Manual, name: str) -> bool:
    """Whether a sentence naming the setting says its digits are typed in seconds."""
    own = [w for w in words(name.replace("_", " ")) if len(w) >= 4]
    for unit in manual.units:
        m = _TYPED_IN_SECONDS_RE.search(unit.text)
        if m and any(w in words(m.group(0)) for w in own):
            return True
    return False


def as_seconds(spec: dict[str, Any]) -> None:
    """A time spec (ranges in hh:mm:ss) made a number of seconds with the same steps."""
    spec["ranges"] = [[parse_hms(lo), parse_hms(hi), int(step)] for lo, hi, step in spec["ranges"]]
    spec["type"] = "numeric"
    spec["unit"] = "s"
    spec.pop("format", None)
    if "initial" in spec and isinstance(spec["initial"], str):
        spec["initial"] = parse_hms(spec["initial"])
