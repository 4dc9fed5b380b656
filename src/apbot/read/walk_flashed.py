"""A walk's field named only by what flashes, its values said beside it.

Manuals of small devices (scales, blood-pressure monitors, watches) name each field of a walk
by what flashes and give its values right there: "The unit flashes: kg or lb.", "The user
number flashes (P1 to P4)." The other field readers want a range with a unit or a bracketed
list of codes; these are read here, and a field they read without a name ("setting") takes
the name of what flashes.
"""

from __future__ import annotations

import copy
import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.build import Builder
from apbot.read.shapes import Evidence
from apbot.read.value_steps import find_step
from apbot.read.values import Range, unit_name
from apbot.read.walk_fields import after_key
from apbot.read.walk_known import flashing_name
from apbot.read.walk_steps import adjuster_hold, held_adds

# "flashes: kg or lb", "blinks: mmHg or kPa"
_FLASHES_COLON_RE = re.compile(r"\b(?:flash(?:es)?|blinks?)\s*:\s*([^.;]+)", re.I)
# "(P1 to P4)", "(U1 – U3)": a run of numbered codes
_CODE_RUN_RE = re.compile(
    r"\(\s*([A-Za-z]{1,2})(\d{1,2})\s*(?:to|–|-|…|\.\.\.)\s*\1(\d{1,2})\s*\)"
)  # ("(U1 to U10)": a run may end in two digits)
_WORD_RE = re.compile(r"°?[A-Za-z][A-Za-z0-9]{0,7}")  # ("°C or °F": a unit's sign before it)
_OR_RE = re.compile(r"\s*,\s*(?:or\s+)?|\s+or\s+|\s*/\s*")


def flashed_field(shown: str) -> dict[str, Any] | None:
    """The field a step opens by saying what flashes, with the values said beside it: a list
    of short words after a colon, or a run of numbered codes in brackets."""
    name = flashing_name(shown)
    if not name:
        return None
    m = _CODE_RUN_RE.search(shown)
    if m and int(m.group(2)) < int(m.group(3)) <= int(m.group(2)) + 9:
        codes = [f"{m.group(1)}{n}" for n in range(int(m.group(2)), int(m.group(3)) + 1)]
        return {
            "name": name,
            "values": codes,
            "show": {c.lower(): c for c in codes},
            "own_name": True,
        }
    m = _FLASHES_COLON_RE.search(shown)
    items = [v.strip() for v in _OR_RE.split(m.group(1))] if m else []
    if 2 <= len(items) <= 6 and all(_WORD_RE.fullmatch(v) for v in items):
        return {"name": name, "values": [v.lower() for v in items], "own_name": True}
    return None


def name_by_flashing(field: dict[str, Any], shown: str) -> dict[str, Any]:
    """A field read without a name of its own takes the name of what flashes."""
    if field.get("name") in ("setting", "") and flashing_name(shown):
        field["name"] = flashing_name(shown)
        field["own_name"] = True
    return field


# "MONTH and the month number flash": the word the display shows beside the field
_SHOWN_WORD_RE = re.compile(r"^([A-Z]{2,10})\s+and\s+(?:the|its)\b")
_HOUR_FLASH_RE = re.compile(r"\bhours?\s+(?:digits?\s+)?(?:flash|blink)", re.I)
_MINUTE_FLASH_RE = re.compile(r"\bminutes?\s+(?:digits?\s+)?(?:flash|blink)", re.I)


def table_field(b: Builder, shown: str, at: int) -> dict[str, Any] | None:
    """A field shown by a display word whose range only the section's table of items gives
    ("MONTH and the month number flash" beside a row "2 | MONTH 1 … 12 | +1 month")."""
    m = _SHOWN_WORD_RE.match(after_key(shown))
    if not m:
        return None
    word = m.group(1)
    cell_re = re.compile(rf"^{word}\s+(\d+)\s*(?:…|\.\.\.|–|-|to)\s*(\d+)$")
    for u in b.manual.units[max(0, at - 40) : at + 40]:
        for cell in u.cells:
            r = cell_re.match(cell.strip())
            if r and int(r.group(1)) < int(r.group(2)):
                rng = Range(float(r.group(1)), float(r.group(2)), "")
                ev = Evidence(ranges=[rng], range_at=at, step=(1.0, ""), step_at=at)
                return {"name": word.lower(), "evidence": ev, "label": word, "own_name": True}
    return None


def joined_clocks(segments: list[tuple[str, str]]) -> tuple[list[tuple[str, str]], set[str]]:
    """A field whose hours flash followed by one whose minutes flash is one time of day set in
    two steps: the two segments joined, and the opening texts of such joined clocks."""
    out: list[tuple[str, str]] = []
    clocks: set[str] = set()
    k = 0
    while k < len(segments):
        opened, text = segments[k]
        nxt = segments[k + 1][0] if k + 1 < len(segments) else ""
        if _HOUR_FLASH_RE.search(opened) and _MINUTE_FLASH_RE.search(nxt):
            out.append((opened, f"{text} {segments[k + 1][1]}"))
            clocks.add(opened)
            k += 2
        else:
            out.append((opened, text))
            k += 1
    return out, clocks


CLOCK_SPEC = {
    "type": "time",
    "ranges": [["00:00:00", "23:59:00", 60]],
    "format": "hh:mm",
    "wrap": True,
}
# "hours flash", "alarm hour blinks": the word before the hours names the clock ("alarm")
_CLOCK_OWNER_RE = re.compile(r"\b([a-z]{3,})\s+hours?\s+(?:digits?\s+)?(?:flash|blink)", re.I)
# "each press moves 5 minutes", "every tap adds 10 min": the minutes' step
_MINUTE_STEP_RE = re.compile(
    r"\b(?:each|every)\s+(?:press|touch|tap|click)\b[^.;]{0,30}?\b(\d{1,2})\s*(?:minutes?|mins?)\b",
    re.I,
)
_NO_OWNER = frozenset({"the", "its", "and", "then", "clock", "time"})


def clock_field(opened: str, text: str, taken: set[str]) -> dict[str, Any]:
    """A joined clock's field: named by the word before its hours ("The alarm hours flash":
    "alarm time"), else "time" (numbered when a clock of one walk took it), its minutes moved
    by the step its text says ("each press moves 5 minutes"), else one."""
    owner = _CLOCK_OWNER_RE.search(opened)
    name = "time"
    if owner and owner.group(1).lower() not in _NO_OWNER:
        name = f"{owner.group(1).lower()} time"
    if name in taken:
        name = f"{name} {sum(n.startswith(name) for n in taken) + 1}"
    said = _MINUTE_STEP_RE.search(text)
    step = (float(said.group(1)), "min") if said else find_step(text)
    minute = 60
    if step and unit_name(step[1]) == "min" and 0 < step[0] < 60 and step[0] == int(step[0]):
        minute = int(step[0]) * 60
    spec = copy.deepcopy(CLOCK_SPEC)
    spec["ranges"] = [["00:00:00", format_hms(24 * 3600 - minute), minute]]
    return {"name": name, "spec": spec, "split": True, "minute": minute}


def clock_effects(
    up: list[str], down: list[str], minute: int = 60
) -> tuple[dict[str, Any], dict[str, Any]]:
    """What the pair does to a clock's hours, and to its minutes (``minute`` seconds a press)."""
    hours = {**{a: {"add": 3600} for a in up}, **{a: {"add": -3600} for a in down}}
    minutes = {**{a: {"add": minute} for a in up}, **{a: {"add": -minute} for a in down}}
    return hours, minutes


def clock_steps(
    var: str, up: list[str], down: list[str], press: str | None, minute: int = 60
) -> list[dict[str, Any]]:
    """The steps of a joined clock: the hours by the pair, the key moving on, the minutes."""
    hours, minutes = clock_effects(up, down, minute)
    return [
        {"actions": up + down, "variable": var, "effect": hours},
        {"actions": [press]},
        {"actions": up + down, "variable": var, "effect": minutes},
    ]


def held_steps(
    b: Builder, adjuster: list[str], steps: list[dict[str, Any]], field: dict[str, Any]
) -> None:
    """Add the lone adjusting key's hold to a field's steps with what its step says it adds
    ("MEM held 2 s adds ten months": +10; "… ten minutes" on a time: +600 s). A joined clock's
    hours and minutes each take the amount said in their own unit."""
    hold = adjuster_hold(b, adjuster)
    said = held_adds(str(field.get("said", ""))) if hold else None
    if hold is None or said is None or "values" in field:
        return
    seconds = {"hour": 3600, "hours": 3600, "minute": 60, "minutes": 60, "second": 1, "seconds": 1}
    for step in steps:
        effect = step.get("effect")
        if not isinstance(effect, dict):
            continue
        if field.get("split"):
            per = 3600 if step is steps[0] else 60
            words = [w for w, s in seconds.items() if s == per]
            amounts = [a for a, u in _all_adds(str(field["said"])) if u in words]
            if not amounts:
                continue
            effect[hold] = {"add": amounts[0] * per}
        else:
            var = b.variables.get(str(step.get("variable")), {})
            per = seconds.get(said[1], 1) if var.get("type") == "time" else 1
            effect[hold] = {"add": said[0] * per}  # a time counts seconds: "ten minutes", 600
        step["actions"] = [*step["actions"], hold]


def _all_adds(text: str) -> list[tuple[int, str]]:
    out = []
    for part in re.split(r"(?<=\))|\.\s", text):
        said = held_adds(part)
        if said:
            out.append(said)
    return out
