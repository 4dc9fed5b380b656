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
from apbot.read.roles_lists import list_range, list_step
from apbot.read.shapes import Evidence
from apbot.read.text import Unit
from apbot.read.value_lists import find_list
from apbot.read.values import NUM, UNIT, find_ranges, find_step

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
# the field named beside the display word that stands for it: "ON and the start time flash",
# "AL and the alarm time appear"
_BESIDE_RE = re.compile(
    r"^([A-Za-z][A-Za-z0-9]{0,5})\s+and\s+the\s+((?:[a-z]+\s){0,2}?[a-z]+)\s+"
    r"(?:flash|appear|blink|light)s?\b"
)
# a display word standing before "appears": "F START appears with …"
_APPEARS_RE = re.compile(r"^([A-Z][A-Z0-9 ]{0,12}?)\s+appears\b")
# a display word and a number: "The display shows dL 0 h."
_SHOWS_CODE_RE = re.compile(r"\bshows\s+([A-Za-z]{1,4})\s+\d")
# a field's name that says nothing of what it is: its key's name leads it ("snooze length")
_BARE = frozenset({"length", "duration", "time", "setting", "value", "level"})
# "Do not touch any key for 5 seconds: the setting is stored", "stored after a few seconds"
_STORED_RE = re.compile(
    r"\b(?:for|after|wait)\s+(?:(\d+)|a few)\s+seconds?\b[^.]*|\bstored\b[^.]*\bseconds\b", re.I
)
# a field set as the one before it: "Set the end hour with ► / ◄ in the same way."
_SAME_WAY_RE = re.compile(r"\b(?:(?:in\s+)?the\s+same\s+way|likewise|as\s+before)\b", re.I)
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
    step = find_step(text)
    listed = find_list(text) if not ranges else None
    if listed and all(re.fullmatch(rf"{NUM}\s*{UNIT}", v, re.I) for v in listed[0]):
        ranges = [list_range(listed[0])]  # "Set the length: 1, 2, 3 or 4 hours."
        step = step or list_step(listed[0])
    if len(ranges) != 1 or not ranges[0].unit:
        return None
    ev = Evidence(ranges=ranges, range_at=at, step=step, step_at=at if step else None)
    return {"name": name or "setting", "evidence": ev}


def _like(one: dict[str, Any], name: str) -> dict[str, Any] | None:
    """The second field of a walk whose step says it is set "in the same way" as the first:
    the first's kind of value under its own name ("the end hour" of a time of day: end_time)."""
    if not name:
        return None
    if "spec" in one:
        return {"name": re.sub(r"(^|_)hours?$", r"\1time", name), "spec": dict(one["spec"])}
    return {"name": name, "evidence": one["evidence"]}


def _field_name(shown: str) -> str:
    m = _SHOWS_RE.search(shown) or _BESIDE_RE.match(_after_key(shown))
    if not m:
        return ""
    return "_".join(
        w for w in m.group(m.lastindex or 1).lower().split() if w not in {"current", "set"}
    )


def _after_key(shown: str) -> str:
    """The step's sentence after the key press that opens it ("Hold X for 3 s. AL and …")."""
    return shown.split(". ", 1)[-1].strip() if ". " in shown else ""


def _label(shown: str, fallback: str) -> str:
    after = _after_key(shown)
    m = _APPEARS_RE.match(after) or _BESIDE_RE.match(after) or _SHOWS_CODE_RE.search(after)
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
        opener = re.compile(rf"^(?:press and |touch and )?hold\s+{re.escape(label)}(?!\w)", re.I)
        for i, unit in enumerate(units):
            if unit.step is None or not opener.match(unit.text):
                continue
            groups = _groups(units, i)
            walk = (_walk(b, groups, label, pairs, i) if press else None) or _one_walk(
                b, groups, label, pairs, i
            )
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
    if two is None and one is not None and _SAME_WAY_RE.search(second):
        two = _like(one, _field_name(moved))
    if one is None or two is None or one["name"] == two["name"]:
        return None
    one["label"] = _label(opened, label)
    two["label"] = _label(moved, label)
    stored = _STORED_RE.search(groups[4][1]) if len(groups) > 4 else None
    timeout = float(stored.group(1) or 5) if stored else None
    return {"pair": pair, "fields": [one, two], "at": at, "timeout": timeout}


def _one_walk(
    b: Builder,
    groups: list[tuple[int, str]],
    label: str,
    pairs: list[tuple[list[str], list[str]]],
    at: int,
) -> dict[str, Any] | None:
    """A hold opening one setting the pair then steps ("1. Hold SNOOZE for 3 seconds. SNZ and
    the length appear. 2. Press ▲ or ▼: 5, 10 … 30 minutes. 3. Wait 5 seconds."), named by
    what the display shows, else by its section ("PRE-SET TIMER"), a bare "length" by its key."""
    if len(groups) < 2:
        return None
    opened, first = groups[0][1], groups[1][1]
    rest = [g[1] for g in groups[2:]]
    if _CLOCK_FIELDS_RE.search(opened) or (
        len(rest) >= 2 and _moves_on(rest[0], label) and _pair_of(b, pairs, rest[1])
    ):
        return None  # the hours of a clock, or a walk through two settings
    pair = _pair_of(b, pairs, first)
    field = _field(b, opened, f"{opened} {first}", at) if pair else None
    if pair is None or field is None:
        return None
    own = _field_name(opened)
    heading = re.sub(r"\([^)]*\)|\d", " ", b.manual.units[at].heading).lower()
    name = own or "_".join(re.findall(r"[a-z]+", heading)[:3])
    if not name or name in _BARE:
        name = "_".join([*re.findall(r"[a-z]+", label.lower()), name or "setting"])
    field.update(name=name, label=_label(opened, label))
    stored = _STORED_RE.search(rest[0]) if rest else None
    timeout = float(stored.group(1) or 5) if stored else None
    return {"pair": pair, "fields": [field], "at": at, "timeout": timeout, "own": bool(own)}


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
    step = find_step(second)  # "Each press moves the time by 5 minutes"
    minute = int(step[0] * 60) if step and step[1] == "min" and 3600 % (step[0] * 60) == 0 else 60
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
        "name": _field_name(opened),  # "AL and the alarm time appear": the alarm time
        "minute": minute,
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
                for steps in b.features.values():  # nor does a choice reset it any more
                    for step in steps:
                        if var in step.get("reset", []):
                            step["reset"] = [r for r in step["reset"] if r != var]
        var = names[0]
        if len(old) == 1 and isinstance(var, str) and not var.endswith("_hold"):
            prefix = f"{var}_"
    return prefix


def _apply(b: Builder, hold: str, press: str | None, walk: dict[str, Any]) -> None:
    """Drop the hold's guessed setting; add the two fields and the feature walking them (named
    after what the hold was read to set, "sleep_period", when that was more than the key's name
    and "hold")."""
    if "clock" in walk:
        _apply_clock(b, hold, press, walk)
        return
    prefix = _drop_guess(b, hold)
    if len(walk["fields"]) == 1:  # one setting: the name the hold was read with, else its own
        field = walk["fields"][0]
        field["name"] = field["name"] if walk.get("own") or not prefix else prefix[:-1]
        prefix = ""
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
    said = f"{hold} opens {names[0]}" + (f", {press} moves to {names[1]}" if names[1:] else "")
    b.note(f"features.{feature}", said, walk["at"])


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


def _apply_clock(b: Builder, hold: str, press: str | None, walk: dict[str, Any]) -> None:
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
    minute = walk["minute"]
    if var is None:
        var = b.unique(walk["name"] or "clock", b.variables)
        b.variables[var] = {
            "label": walk["clock"],
            "type": "time",
            "ranges": [["00:00:00", format_hms(24 * 3600 - minute), minute]],
            "format": "hh:mm",
        }
        b.note(f"variables.{var}", "a time of day the held key's steps set", walk["at"])
    b.variables[var]["wrap"] = True
    hours = {**{a: {"add": 3600} for a in up}, **{a: {"add": -3600} for a in down}}
    minutes = {**{a: {"add": minute} for a in up}, **{a: {"add": -minute} for a in down}}
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
