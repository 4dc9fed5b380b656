"""A held key that opens a walk through two settings, each set with the stepping pair.

Manuals write it as numbered steps: "1. Hold SLEEP for 3 seconds. The display shows the start
time. 2. Press + or - to change the start time in steps of 30 minutes. After 23:30 comes 00:00.
3. Touch SLEEP briefly. The display shows the length. 4. Press + or - to change the length,
from 2 to 12 hours." The hold opens the first setting, a short press of the same key moves on
to the second, and the pair sets each. Without this reading the hold was guessed as a switch
of its own and both settings were missing.

The same steps may walk the hours, then the minutes, of one clock: "1. Hold CLOCK for 3
seconds. The hours flash. 2. Press ▲ or ▼ to set the hours. 3. Press CLOCK. The minutes
flash. 4. Press ▲ or ▼ to set the minutes (hold for 2 seconds: 10 minutes at a time)." The
pair then moves the time of day by an hour, and after the press by a minute.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.build import Builder
from apbot.read.roles_fasthold import held_time_step
from apbot.read.shapes import Evidence
from apbot.read.text import Unit
from apbot.read.values import find_ranges, find_step

# "after 23:30 comes 00:00", "After 23:45 the time continues at 00:00": the last time of a day
_DAY_WRAP_RE = re.compile(
    r"\b(?:after|past)\s+([01]?\d|2[0-3]):([0-5]\d)\b[^.;]{0,40}?\b0?0:00\b", re.I
)
# what the display shows on opening a field: "shows the start time", "appears with the length"
_SHOWS_RE = re.compile(
    r"\b(?:shows|displays|appears with|flashes with)\s+the\s+((?:[a-z]+\s){0,2}?[a-z]+)"
    r"(?=\s*(?:[,.(]|\bof\b|\bbeing\b|\be\.g\.|$))",
    re.I,
)
# a display word standing before "appears": "F START appears with …"
_APPEARS_RE = re.compile(r"^([A-Z][A-Z0-9 ]{0,12}?)\s+appears\b")
# "Do not touch any key for 5 seconds: the setting is stored", "stored after a few seconds"
_STORED_RE = re.compile(
    r"\b(?:for|after)\s+(?:(\d+)|a few)\s+seconds?\b[^.]*|\bstored\b[^.]*\bseconds\b", re.I
)
_CLOCK_FIELDS_RE = re.compile(r"\bhours?\b[^.]*\bflash", re.I)
_HOURS_RE = re.compile(r"\bhours?\b", re.I)
_MINUTES_RE = re.compile(r"\bminutes?\b", re.I)


def _says(text: str, label: str) -> bool:
    return re.search(rf"(?<!\w){re.escape(label)}(?!\w)", text, re.I) is not None


def _pairs(b: Builder) -> list[tuple[list[str], list[str]]]:
    """The stepping pairs the model already has: presses that step one setting up and down."""
    press = {i.name for i in b.infos if i.skill == "press"}
    out: list[tuple[list[str], list[str]]] = []
    for steps in b.features.values():
        for step in steps:
            effect = step.get("effect")
            if not isinstance(effect, dict):
                continue
            up = [a for a, e in effect.items() if e == "next" and a in press]
            down = [a for a, e in effect.items() if e == "prev" and a in press]
            if up and down and (up, down) not in out:
                out.append((up, down))
    return out


def _groups(units: list[Unit], i: int) -> list[tuple[int, str]]:
    """The numbered steps from unit ``i`` on, each with the sentences that follow it."""
    out: list[tuple[int, str]] = []
    first = units[i].step
    for u in units[i:]:
        if u.step is not None:
            if first is None or u.step != first + len(out) or len(out) >= 5:
                break
            out.append((u.step, u.text))
        elif u.cells or u.heading != units[i].heading:
            break
        else:
            out[-1] = (out[-1][0], f"{out[-1][1]} {u.text}")
    return out


def _field(b: Builder, shown: str, text: str, at: int) -> dict[str, Any] | None:
    """The setting a field holds: a time of day that wraps at midnight, else a range in a unit."""
    name = _field_name(shown)
    m = _DAY_WRAP_RE.search(text)
    if m:
        last = int(m.group(1)) * 3600 + int(m.group(2)) * 60
        every = 24 * 3600 - last
        if every <= 0 or every > 3 * 3600:
            return None
        if name:  # "the start hour" of a time of day: its start time
            name = re.sub(r"(^|_)hours?$", r"\1time", name)
        spec = {
            "type": "time",
            "ranges": [["00:00:00", format_hms(last), every]],
            "format": "hh:mm",
            "wrap": True,
        }
        return {"name": name or "time", "spec": spec}
    ranges = find_ranges(text)
    if len(ranges) != 1 or not ranges[0].unit:
        return None
    step = find_step(text)
    ev = Evidence(ranges=ranges, range_at=at, step=step, step_at=at if step else None)
    return {"name": name or "setting", "evidence": ev}


def _field_name(shown: str) -> str:
    m = _SHOWS_RE.search(shown)
    if not m:
        return ""
    return "_".join(w for w in m.group(1).lower().split() if w not in {"current", "set"})


def _label(shown: str, fallback: str) -> str:
    m = _APPEARS_RE.match(shown.split(". ", 1)[-1].strip()) if ". " in shown else None
    return m.group(1).strip() if m else fallback


def read_held_walks(b: Builder) -> None:
    """Replace a held key's guessed switch by the two settings its numbered steps walk."""
    units = b.manual.units
    pairs = _pairs(b)
    if not pairs:
        return
    for info in b.infos:
        if info.skill != "hold" or len(info.controls) != 1 or info.controls[0] not in b.labels:
            continue
        token = info.controls[0]
        press = next(
            (i.name for i in b.infos if i.skill == "press" and i.controls == (token,)), None
        )
        label = b.labels[token].text
        if press is None:
            continue
        opener = re.compile(rf"^(?:press and |touch and )?hold\s+{re.escape(label)}(?!\w)", re.I)
        for i, unit in enumerate(units):
            if unit.step is None or not opener.match(unit.text):
                continue
            walk = _walk(b, _groups(units, i), label, pairs, i)
            if walk is not None:
                _apply(b, info.name, press, walk)
                break


def _walk(
    b: Builder,
    groups: list[tuple[int, str]],
    label: str,
    pairs: list[tuple[list[str], list[str]]],
    at: int,
) -> dict[str, Any] | None:
    if len(groups) < 4:
        return None
    opened, first, moved, second = (g[1] for g in groups[:4])
    if not _moves_on(moved, label):
        return None
    pair = _pair_of(b, pairs, first)
    if pair is None or _pair_of(b, pairs, second) != pair:
        return None
    if _CLOCK_FIELDS_RE.search(opened):  # the hours, then the minutes, of one clock
        return _clock_walk(b, groups, label, pair, at)
    one = _field(b, opened, f"{opened} {first}", at)
    two = _field(b, moved, f"{moved} {second}", at)
    if one is None or two is None or one["name"] == two["name"]:
        return None
    one["label"] = _label(opened, label)
    two["label"] = _label(moved, label)
    stored = _STORED_RE.search(groups[4][1]) if len(groups) > 4 else None
    timeout = float(stored.group(1) or 5) if stored else None
    return {"pair": pair, "fields": [one, two], "at": at, "timeout": timeout}


def _moves_on(text: str, label: str) -> bool:
    """A step that is a short press of the walk's key ("Press CLOCK briefly.")."""
    return (
        re.match(rf"^(?:press|touch)\s+{re.escape(label)}(?!\w)(?!\s+and\b)", text, re.I)
        is not None
    )


def _pair_of(
    b: Builder, pairs: list[tuple[list[str], list[str]]], text: str
) -> tuple[list[str], list[str]] | None:
    """The stepping pair a step names with both its keys ("Press ▲ or ▼ to …")."""
    for up, down in pairs:
        ups = [b.labels[t].text for a in up for t in _controls(b, a) if t in b.labels]
        downs = [b.labels[t].text for a in down for t in _controls(b, a) if t in b.labels]
        if any(_says(text, x) for x in ups) and any(_says(text, x) for x in downs):
            return up, down
    return None


def _clock_walk(
    b: Builder,
    groups: list[tuple[int, str]],
    label: str,
    pair: tuple[list[str], list[str]],
    at: int,
) -> dict[str, Any] | None:
    """The hours, then (after a press of the key) the minutes of one time of day: the pair
    moves it by an hour, then by a minute (and a hold of the pair by what the manual says)."""
    opened, first, moved, second = (g[1] for g in groups[:4])
    if not _HOURS_RE.search(first) or not _MINUTES_RE.search(f"{moved} {second}"):
        return None
    if any(r.unit in ("h", "") and r.high < 23 for r in find_ranges(f"{opened} {first}")):
        return None  # "from 0 to 12 hours": a duration (a delay), not a time of day
    held = held_time_step(second)
    holds: dict[str, int] = {}
    for k, side in enumerate(pair):
        for action in side:
            controls = _controls(b, action)
            for info in b.infos:
                if held and info.skill == "hold" and info.controls == controls:
                    holds[info.name] = held if k == 0 else -held
    last = groups[4][1] if len(groups) > 4 else ""
    confirm = _moves_on(last, label)
    stored = None if confirm else _STORED_RE.search(last)
    timeout = float(stored.group(1) or 5) if stored else None
    return {
        "pair": pair,
        "clock": _label(opened, label),
        "holds": holds,
        "confirm": confirm,
        "at": at,
        "timeout": timeout,
    }


def _controls(b: Builder, action: str) -> tuple[str, ...]:
    return next((i.controls for i in b.infos if i.name == action), ())


def _drop_guess(b: Builder, hold: str) -> str:
    """Drop the setting the hold alone was guessed to set; return its name as a prefix
    ("sleep_period_") when that was more than the key's name and "hold"."""
    prefix = ""
    for fname, old in list(b.features.items()):
        if not old or old[0].get("actions") != [hold]:
            continue
        names = [s.get("variable") for s in old]
        if len(old) > 1 and not all(v is None or v.endswith("_hold") for v in names):
            continue  # (a hold opening a setting read as the key's own "…_hold" is a guess)
        del b.features[fname]
        for var in names:
            used = any(s.get("variable") == var for st in b.features.values() for s in st)
            if var in b.variables and not used:
                del b.variables[var]
        var = names[0]
        if len(old) == 1 and isinstance(var, str) and not var.endswith("_hold"):
            prefix = f"{var}_"
    return prefix


def _apply(b: Builder, hold: str, press: str, walk: dict[str, Any]) -> None:
    """Drop the hold's guessed setting; add the two fields and the feature walking them (named
    after what the hold was read to set, "sleep_period", when that was more than the key's name
    and "hold")."""
    if "clock" in walk:
        _apply_clock(b, hold, press, walk)
        return
    prefix = _drop_guess(b, hold)
    up, down = walk["pair"]
    effect = {**{a: "next" for a in up}, **{a: "prev" for a in down}}
    steps: list[dict[str, Any]] = [{"actions": [hold]}]
    names = []
    for k, field in enumerate(walk["fields"]):
        if "spec" in field:
            var = b.unique(prefix + field["name"], b.variables)
            b.variables[var] = {"label": field["label"], **field["spec"]}
            b.note(f"variables.{var}", "a time of day the held key's steps set", walk["at"])
        else:
            var = b.add_number(
                prefix + field["name"], field["label"], field["evidence"], cyclic=False
            )
        if k:
            steps.append({"actions": [press]})
        steps.append({"actions": up + down, "variable": var, "effect": dict(effect)})
        names.append(var)
    if walk["timeout"] is not None:  # the walk ends by itself once no key is touched
        for step in steps:
            step["timeout"] = walk["timeout"]
    feature = f"set_{names[0]}"
    b.feature(feature, steps)
    b.note(
        f"features.{feature}", f"{hold} opens {names[0]}, {press} moves to {names[1]}", walk["at"]
    )


def _day_clock(spec: dict[str, Any]) -> bool:
    """A time of day set to the minute (00:00–23:59 by one minute), not a duration or a time
    set in steps of half an hour."""
    ranges = spec.get("ranges") or []
    return (
        spec.get("type") == "time"
        and len(ranges) == 1
        and str(ranges[0][1]) >= "23:59"
        and ranges[0][2] == 60
    )


def _apply_clock(b: Builder, hold: str, press: str, walk: dict[str, Any]) -> None:
    """Add the clock walk; the time it sets is the time the key's press was read to open with
    the pair (that reading, a press alone opening the minutes, is dropped), else a new one."""
    _drop_guess(b, hold)
    up, down = walk["pair"]
    var = None
    for fname, old in list(b.features.items()):
        if (
            len(old) == 2
            and old[0].get("actions") == [press]
            and "variable" not in old[0]
            and set(up + down) <= set(old[1].get("actions", []))
            and _day_clock(b.variables.get(str(old[1].get("variable")), {}))
        ):
            var = old[1]["variable"]
            del b.features[fname]
            break
    if var is None:
        var = b.unique("clock", b.variables)
        b.variables[var] = {
            "label": walk["clock"],
            "type": "time",
            "ranges": [["00:00:00", "23:59:00", 60]],
            "format": "hh:mm",
        }
        b.note(f"variables.{var}", "a time of day the held key's steps set", walk["at"])
    b.variables[var]["wrap"] = True
    hours = {**{a: {"add": 3600} for a in up}, **{a: {"add": -3600} for a in down}}
    minutes = {**{a: {"add": 60} for a in up}, **{a: {"add": -60} for a in down}}
    minutes.update({a: {"add": n} for a, n in walk["holds"].items()})
    steps: list[dict[str, Any]] = [
        {"actions": [hold]},
        {"actions": up + down, "variable": var, "effect": hours},
        {"actions": [press]},
        {"actions": list(minutes), "variable": var, "effect": minutes},
    ]
    if walk["confirm"]:
        steps.append({"actions": [press]})
    if walk["timeout"] is not None:
        for step in steps:
            step["timeout"] = walk["timeout"]
    feature = b.unique(f"set_{var}", b.features)
    b.feature(feature, steps)
    b.note(
        f"features.{feature}", f"{hold} opens the hours of {var}, {press} its minutes", walk["at"]
    )
