"""A key that switches a timed function on or off, whose time the stepping pair then moves.

"TIMER — Switches the ready-time on or off." and, in its section, "Press ▲ or ▼ to move the
ready-time by 30 minutes per press": the key is a toggle and also opens a time (a time of day
when the manual says so) that ▲ / ▼ step. Without this the key is only a toggle and the time
a user asks for ("hot water at half past six") has no setting to go to.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.clock_format import twelve_hour_clock
from apbot.read.labels import words
from apbot.read.roles_common import TIME_WORDS, label_of
from apbot.read.value_steps import find_step

_SWITCHED_RE = re.compile(
    r"\bswitch(?:es)?\s+(?:the\s+)?([a-z][\w-]*(?:\s[a-z][\w-]*)?)\s+(?:function\s+)?"
    r"(?:on\s+(?:or|and)\s+off|on/off)\b",
    re.I,
)
_PAIR_WORDS = r"(?:▲|▼|\+|-|–|up|down|plus|minus)"
_DAY_RE = re.compile(
    r"\btime of day\b|\bo'clock\b|\bready[- ](?:at|by|time)\b|\bfinish(?:ing)?[- ]time\b"
    r"|\bafter 23:\d\d\b|\b23:\d\d\b",
    re.I,
)


def switched_time(b: Builder, key: ActionInfo, pair: dict[str, list[str]] | None) -> bool:
    """Give ``key`` a toggle and a time the shared pair moves, when the manual says both;
    False (nothing added) otherwise."""
    if not pair or not pair.get("up") or not pair.get("down") or key.skill != "press":
        return False
    token = key.controls[0]
    if token not in b.labels or not set(words(token.replace("_", " "))) & TIME_WORDS:
        return False
    units = b.manual.units
    mentions = b.labels[token].mentions
    switched = next((i for i in mentions if _SWITCHED_RE.search(units[i].text)), None)
    if switched is None:
        return False
    m = _SWITCHED_RE.search(units[switched].text)
    noun = m.group(1).lower() if m else ""
    if not noun or not set(words(noun)) & (TIME_WORDS | {"ready", "finish", "preset"}):
        return False
    said = re.compile(
        rf"{_PAIR_WORDS}[^.]{{0,40}}\b(?:to\s+)?(?:move|change|set|adjust)\w*\s+the\s+"
        rf"{re.escape(noun)}\b",
        re.I,
    )
    moved = [i for i, u in enumerate(units) if said.search(u.text)]
    if not moved:
        return False
    near = [i for k in moved for i in range(max(0, k - 3), min(k + 4, len(units)))]
    step = 60
    for i in moved + near:
        found = find_step(units[i].text)
        if found and found[1] == "min" and found[0] in (1, 5, 10, 15, 30, 60):
            step = int(found[0] * 60)
            break
        if found and found[1] == "h" and found[0] == 1:
            step = 3600
            break
    day = any(_DAY_RE.search(units[i].text) for i in [switched, *moved, *near])
    twelve = twelve_hour_clock(units)
    low, high = (3600, 12 * 3600 + 59 * 60) if twelve and day else (0, 23 * 3600 + 59 * 60)
    if not day:
        low, high = 0, 24 * 3600
    high -= (high - low) % step
    lab = label_of(b, token)
    toggle = b.add_toggle(re.sub(r"\W+", "_", token), lab, switched)
    var = b.unique(re.sub(r"\W+", "_", noun).strip("_") or f"{token}_time", b.variables)
    spec: dict[str, Any] = {
        "type": "time",
        "ranges": [[format_hms(low), format_hms(high), step]],
        "format": "hh:mm" if day else "h:mm",
        "wrap": day,
        "label": noun.upper(),
    }
    b.variables[var] = spec
    _shown(b, toggle, var, noun)
    first = _FIRST_RE.search(" ".join(units[i].text for i in [*moved, *near]))
    if first and day:  # "(06:00 the first time)"
        h, mnt = int(first.group(1)), int(first.group(2))
        if 3600 * h + 60 * mnt <= high and (3600 * h + 60 * mnt - low) % step == 0:
            spec["initial"] = format_hms(3600 * h + 60 * mnt)
    up, down = pair["up"], pair["down"]
    effect = {**{a: "next" for a in up}, **{a: "prev" for a in down}}
    b.feature(
        f"set_{var}",
        [
            {"actions": [key.name], "variable": toggle, "effect": "toggle"},
            {"actions": [*up, *down], "variable": var, "effect": effect},
        ],
    )
    what = "a time of day" if day else "a duration"
    b.note(
        f"features.set_{var}", f"{lab} switches it on, then the pair moves it ({what})", moved[0]
    )
    return True


_FIRST_RE = re.compile(r"\b(\d{1,2}):(\d\d)\s+(?:the first time|at first|by default)\b", re.I)
_ROW_RE = re.compile(r"^([A-Z][A-Z-]{1,11})\s+(\d{1,2}:\d\d|--:--)\s{2,}(.+)$")


def _shown(b: Builder, toggle: str, var: str, noun: str) -> None:
    """A display legend's rows "READY 06:30   Ready-time switched on, hot water at 06:30" and
    "READY --:--   No ready-time": what the display shows with the function on (the word and
    the time) and off."""
    on = off = None
    for unit in b.manual.units:
        m = _ROW_RE.match(unit.text)
        if not m or noun.split()[0].lower() not in m.group(3).lower():
            continue
        if m.group(2) == "--:--":
            off = f"{m.group(1)} --:--"
        elif re.search(r"\bon\b", m.group(3), re.I):
            on = f"{m.group(1)} {{{var}}}"
    if on:
        b.variables[toggle]["show"] = {"off": off or "", "on": on}
        if toggle in b.indicators:
            b.indicators.remove(toggle)
        b.note(f"variables.{toggle}.show", f"the display shows {on} while it is on")
