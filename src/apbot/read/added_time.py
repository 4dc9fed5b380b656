"""Which time an add-time key (+30 SEC, ADD 1 MIN) adds to, when the panel has several.

A manual says it where it explains the key ("+30 SEC adds 30 seconds to the cooking time"), so
the time whose own words the key's sentences use is the one; a time of day (a clock) is never
lengthened by a key that adds cooking seconds, so it comes last. Only then the belief's order
(the manual's), never the order the robot listed its actions in.
"""

from __future__ import annotations

from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import label_of, mentions_of

# words every time setting's name may hold: they tell no time from another
_GENERIC = frozenset({"time", "timer", "set", "setting"})
_OF_DAY = frozenset({"clock"})


def added_time(b: Builder, key: ActionInfo) -> str | None:
    """The time setting ``key`` adds to: the one its sentences name, a clock last; None when
    the belief has no time setting."""
    times = [v for v, spec in b.variables.items() if spec.get("type") == "time"]
    if not times:
        return None
    said = {
        w for i in mentions_of(b, key.controls[0]) for w in words(b.manual.units[i].text)
    } - set(words(label_of(b, key.controls[0])))
    return min(times, key=lambda v: _rank(v, b.variables[v], said))


def _rank(name: str, spec: dict[str, Any], said: set[str]) -> tuple[int, bool]:
    """Fewer of its own words unsaid first ("cooking time" names TIME COOK), then not a clock."""
    own = (set(words(name)) | set(words(str(spec.get("label", ""))))) - _GENERIC
    named = sum(any(w.startswith(o) for w in said) for o in own if len(o) >= 3)
    return (-named, bool(own & _OF_DAY))
