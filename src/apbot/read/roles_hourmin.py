"""HOUR and MIN keys shared by the time settings ("HOUR / MIN move the hours and the minutes
forward, when setting the clock or the finish time"): each time key (CLOCK, TIMER, READY AT,
PRESET, DELAY) opens its time, which the two keys then move forward by an hour and a minute."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.clock_format import twelve_hour_clock
from apbot.read.roles_common import label_of, var_name
from apbot.read.value_steps import find_step
from apbot.read.values import ON_OFF_RE

_HOUR = {"hour", "hours", "hr", "hrs"}
_MINUTE = {"min", "mins", "minute", "minutes"}
_TIME_KEYS = {"clock", "timer", "ready", "preset", "delay", "finish", "reserve", "time"}
_FINISH_RE = re.compile(r"\bfinish(?:ing)?[- ]time\b|\bready[- ](?:at|by|time)\b", re.I)
_DAY_RE = re.compile(
    r"\b(?:finish(?:ing)? time|ready (?:at|by)|time of day|o'clock|24-hour|12-hour|\d{1,2}:\d\d)\b",
    re.I,
)


def hour_minute_keys(infos: list[ActionInfo], done: set[str]) -> tuple[str, str] | None:
    """The panel's HOUR and MIN presses, when it has exactly one of each still without a role."""
    hours = [i.name for i in infos if i.skill == "press" and i.name not in done
             and len(i.controls) == 1 and set(i.controls[0].split("_")) <= _HOUR]  # fmt: skip
    minutes = [i.name for i in infos if i.skill == "press" and i.name not in done
               and len(i.controls) == 1 and set(i.controls[0].split("_")) <= _MINUTE]  # fmt: skip
    return (hours[0], minutes[0]) if len(hours) == 1 and len(minutes) == 1 else None


def assign_hour_minute(b: Builder, keys: list[ActionInfo], pair: tuple[str, str]) -> list[str]:
    """Give each time key a feature: the key, then HOUR / MIN adding an hour / a step of minutes
    to its time. Returns the actions given a role (none when no key takes the pair)."""
    hour, minute = pair
    units = b.manual.units

    def finish_key(token: str) -> bool:  # "DONE BY — switches the finish-time function on"
        said = b.labels[token].mentions[:2] if token in b.labels else []
        return any(_FINISH_RE.search(units[i].text) for i in said)

    pair_tokens = [k.controls[0] for k in keys if k.name in pair and len(k.controls) == 1]
    pair_said = {i for t in pair_tokens if t in b.labels for i in b.labels[t].mentions}

    def with_pair(token: str) -> bool:
        """HOUR / MIN are named near the key ("Press CLOCK. … Press HOUR …"), or their own
        sentences name it ("HOUR / MIN set the clock"): a time word in a key's name alone
        ("COOK TIME" of a +/− pair) gives it no HOUR / MIN."""
        said = b.labels[token].mentions if token in b.labels else []
        if {j for i in said for j in range(i, i + 3)} & pair_said:
            return True
        name = re.compile(rf"\b{re.escape(label_of(b, token))}\b", re.I)
        return any(name.search(units[i].text) for i in pair_said)

    timed = [
        k
        for k in keys
        if k.skill in ("press", "hold")
        and len(k.controls) == 1
        and (set(k.controls[0].split("_")) & _TIME_KEYS or finish_key(k.controls[0]))
        and (not pair_said or with_pair(k.controls[0]))
    ]
    if not timed:
        return []
    used = [hour, minute]
    for key in timed:
        token = key.controls[0]
        name = var_name(b, key).removesuffix("_hold")
        mentions = b.labels[token].mentions if token in b.labels else []
        context = [i for m in mentions for i in range(m, min(m + 3, len(b.manual.units)))]
        clock = "clock" in token.split("_")
        day = clock or any(_DAY_RE.search(b.manual.units[i].text) for i in context)
        step = 60
        if day and not clock:  # a finish time's step may stand where the finish time is named
            context += [i for i, u in enumerate(b.manual.units) if _FINISH_RE.search(u.text)]
        for i in context:
            found = find_step(b.manual.units[i].text)
            if found and found[1] == "min" and found[0] in (1, 5, 10, 15, 30):
                step = int(found[0] * 60)
                break
        twelve = twelve_hour_clock(b.manual.units)
        low, high = (3600, 12 * 3600 + 59 * 60) if twelve and day else (0, 23 * 3600 + 59 * 60)
        if not day:
            high = 12 * 3600  # a duration: half a day, the loop finds the end
        high -= (high - low) % step
        var = b.unique(name, b.variables)
        spec: dict[str, Any] = {
            "type": "time",
            "ranges": [[format_hms(low), format_hms(high), step]],
            "format": "hh:mm",
            "wrap": True,
            "label": label_of(b, token),
        }
        b.variables[var] = spec
        effect = {hour: {"add": "01:00:00"}, minute: {"add": format_hms(step)}}
        first: dict[str, Any] = {"actions": [key.name]}
        switched = [i for i in mentions if ON_OFF_RE.search(b.manual.units[i].text)]
        if switched and not clock:  # "READY AT switches the finish-time function on or off"
            toggle = b.add_toggle(f"{var}_on", label_of(b, token), switched[0])
            first = {"actions": [key.name], "variable": toggle, "effect": "toggle"}
        steps = [first, {"actions": [hour, minute], "variable": var, "effect": effect}]
        b.feature(f"set_{var}", steps)
        what = "a time of day" if day else "a duration"
        b.note(f"features.set_{var}", f"{label_of(b, token)} then HOUR / MIN ({what})",
               mentions[0] if mentions else None)  # fmt: skip
        used.append(key.name)
    return used
