"""A time typed on the number keys as minutes and seconds: "Type the minutes and the seconds …
1 2 0 0 → 12:00 … up to 99 minutes 59 seconds".

A key named for a clock (SET CLOCK, CLOCK) that the number keys follow was read as the time of
day: hours and minutes, to 23:59. Game clocks, countdowns and kitchen timers are typed as
minutes and seconds instead, and their manuals say so in the entry's own steps ("type the
minutes and the seconds", "up to 99 minutes 59 seconds"). Such an entry is minutes and seconds,
every second, up to the top the manual gives; both sayings are wanted ("times are entered as
minutes and seconds" alone, near a microwave's CLOCK, is about its cooking times). A variable
named after its key's verb ("set_clock") is named after what it sets ("clock").
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.build import Builder

# "type the minutes and the seconds", "enter minutes and seconds"
_MIN_SEC_RE = re.compile(r"\bminutes\s+and\s+(?:the\s+)?seconds\b", re.IGNORECASE)
# "up to 99 minutes 59 seconds", "as long as 59 min 59 s"
_TOP_RE = re.compile(
    r"\b(?:up\s+to|as\s+long\s+as|at\s+most|maximum(?:\s+of)?)\s+(\d{1,3})\s*(?:minutes|min)\s*"
    r"(?:and\s+)?(\d{1,2})\s*(?:seconds|sec|s)\b",
    re.IGNORECASE,
)
# the clock's own steps set the time of day: "enter the time of day", "hours and minutes"
_DAY_RE = re.compile(
    r"\btime\s+of\s+(?:the\s+)?day\b|\bhours?\s+and\s+(?:the\s+)?minutes?\b|\b(?:12|24)[- ]hour\b",
    re.IGNORECASE,
)


def _said_near(b: Builder, key: str) -> tuple[int, int] | None:
    """(unit saying minutes and seconds, unit giving the top) near the key's mentions."""
    if key not in b.labels:
        return None
    mentions = b.labels[key].mentions
    units = b.manual.units
    near = sorted({j for i in mentions for j in range(max(0, i - 2), min(len(units), i + 6))})
    said = next((j for j in near if _MIN_SEC_RE.search(units[j].text)), None)
    top = next((j for j in near if _TOP_RE.search(units[j].text)), None)
    if said is None or top is None:
        return None  # (both: "times are entered as minutes and seconds" alone is a cook time's)
    if any(_DAY_RE.search(units[j].text) for j in near):
        return None  # (a microwave's CLOCK beside its cook times: the time of day, review31)
    return said, top


def read_typed_minutes(b: Builder) -> None:
    """Make a clock typed after its key as hours and minutes one of minutes and seconds when
    the entry's own steps say the number keys type minutes and seconds."""
    for steps in list(b.features.values()):
        if len(steps) < 2 or len(steps[0].get("actions") or []) != 1:
            continue
        var = steps[1].get("variable")
        spec = b.variables.get(var or "")
        if var is None or spec is None or spec.get("type") != "time":
            continue
        if (spec.get("entry") or {}).get("format") != "hh:mm":
            continue
        key = next((i for i in b.infos if i.name == steps[0]["actions"][0]), None)
        if key is None or len(key.controls) != 1:
            continue
        found = _said_near(b, key.controls[0])
        if found is None:
            continue
        top = "01:39:59"
        if m := _TOP_RE.search(b.manual.units[found[1]].text):
            top = format_hms(int(m.group(1)) * 60 + min(59, int(m.group(2))))
        spec.update(ranges=[["00:00:00", top, 1]], format="mm:ss", entry={"format": "mm:ss"})
        spec.pop("unit", None)
        b.unread.discard(var)
        whole = int(top[:2]) * 60 + int(top[3:5])
        b.note(f"variables.{var}", f"minutes and seconds typed, up to {whole}:{top[6:]}", found[0])
        _name_after_object(b, var, spec)


def _name_after_object(b: Builder, var: str, spec: dict[str, Any]) -> None:
    """``set_clock`` → ``clock`` when that name is free: the verb is the key's, not the time's."""
    if not var.startswith("set_") or var[4:] in b.variables or not var[4:]:
        return
    new = var[4:]
    b.variables = {(new if n == var else n): s for n, s in b.variables.items()}
    for steps in b.features.values():
        for st in steps:
            if st.get("variable") == var:
                st["variable"] = new
    for g in b.guards:
        if var in (g.get("when") or {}):
            g["when"] = {(new if k == var else k): v for k, v in g["when"].items()}
    b.indicators = [new if v == var else v for v in b.indicators]
    if spec.get("label", "").upper().startswith("SET "):
        spec["label"] = spec["label"][4:]
