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

from apbot.read.build import Builder
from apbot.read.roles_fasthold import held_time_step
from apbot.read.value_steps import find_step
from apbot.read.values import find_ranges
from apbot.read.walk_apply import apply_walk
from apbot.read.walk_ends import pause_seconds, walk_timeout
from apbot.read.walk_fields import (
    SAME_WAY_RE,
    field_label,
    field_name,
    like,
    read_field,
    read_more_field,
)
from apbot.read.walk_flashed import (
    clock_field,
    flashed_field,
    joined_clocks,
    name_by_flashing,
    table_field,
)
from apbot.read.walk_keys import controls_of, moves_on, pair_of, stepping_pairs
from apbot.read.walk_known import flashing_name, known_field
from apbot.read.walk_like import further_like, named_by_code
from apbot.read.walk_listed import listed_field
from apbot.read.walk_order import read_coded_field, with_step
from apbot.read.walk_steps import moves_at_ends, prose_opener, single_keys, walk_steps

# a field's name that says nothing of what it is: its key's name leads it ("snooze length")
_BARE = frozenset({"length", "duration", "time", "setting", "value", "level"})
# a step the walk may pass over: "To keep it unchanged, go straight to step 3."
_SKIP_RE = re.compile(
    r"\bgo\s+(?:straight|directly)\s+(?:on\s+)?to\s+step\b|\bskip\s+(?:this|the)\s+step\b", re.I
)
_CLOCK_FIELDS_RE = re.compile(r"\bhours?\b[^.]*\bflash", re.I)
_HOURS_RE = re.compile(r"\bhours?\b", re.I)
_MINUTES_RE = re.compile(r"\bminutes?\b", re.I)


def read_held_walks(b: Builder) -> None:
    """Replace a held key's guessed switch by the two settings its numbered steps walk."""
    units = b.manual.units
    pairs = stepping_pairs(b)
    stepping = {a for up, down in pairs for a in up + down}
    pairs += single_keys(b, pairs)
    if not pairs:
        return
    for info in b.infos:
        if info.skill != "hold" or len(info.controls) != 1 or info.controls[0] not in b.labels:
            continue
        token = info.controls[0]
        paired = info.name in stepping or any(
            i.controls == (token,) and i.name in stepping for i in b.infos
        )
        press = next(
            (i.name for i in b.infos if i.skill == "press" and i.controls == (token,)), None
        )
        label = b.labels[token].text
        opener = re.compile(rf"^(?:press and |touch and )?hold\s+{re.escape(label)}(?!\w)", re.I)
        for i, unit in enumerate(units):
            if not opener.match(unit.text) or (
                unit.step is None and not prose_opener(unit, paired)
            ):
                continue
            groups = walk_steps(units, i)
            walk = (stepped_walk(b, groups, label, pairs, i) if press else None) or _one_walk(
                b, groups, label, pairs, i
            )
            if walk is not None:
                apply_walk(b, info.name, press, walk)
                break


def stepped_walk(
    b: Builder,
    groups: list[tuple[int, str]],
    label: str,
    pairs: list[tuple[list[str], list[str]]],
    at: int,
) -> dict[str, Any] | None:
    """Two or more settings the held key's steps walk: the hold opens the first, each short
    press of the key the next, and the pair sets each."""
    groups = moves_at_ends(groups, label)
    if len(groups) < 3:
        return None
    later = " ".join(t for _, t in groups[1:])
    if _CLOCK_FIELDS_RE.search(groups[0][1]) and _MINUTES_RE.search(later):
        # the hours, then the minutes, of one clock (an hour with no minutes after it is a
        # field of its own: "the switch-on hour flashes … then the light period")
        if len(groups) < 4 or not moves_on(groups[2][1], label):
            return None
        pair = pair_of(b, pairs, groups[1][1])
        if pair is None or pair_of(b, pairs, groups[3][1]) != pair:
            return None
        return _clock_walk(b, groups, label, pair, at)
    segments, end = _segments(b, groups, label, pairs)
    segments, clocks = joined_clocks(segments)
    fields: list[dict[str, Any]] = []
    pair = None
    heading = b.manual.units[at].heading
    for opened, text in segments:
        own = pair_of(b, pairs, text) or (pair if fields and SAME_WAY_RE.search(text) else None)
        if own is None or (pair is not None and own != pair):
            break
        field = (
            (clock_field(opened, text, {f["name"] for f in fields}) if opened in clocks else None)
            or read_field(opened, text, at, beside=True)
            or read_more_field(opened, text, at)
            or read_coded_field(opened, text, at)
            or known_field(b, opened, at)
            or flashed_field(opened)
            or table_field(b, opened, at)
        )
        field = with_step(name_by_flashing(field, opened), text, at) if field else None
        if field is None and fields and "values" not in fields[-1] and SAME_WAY_RE.search(text):
            field = like(fields[-1], field_name(opened, beside=True) or "setting")
        field = named_by_code(field, opened, heading) if field else None
        if field is None or any(f["name"] == field["name"] for f in fields):
            break
        shown = field.get("label") or field_label(opened, label, example="values" not in field)
        field.update(label=shown, optional=bool(_SKIP_RE.search(text)), said=text)
        pair = own
        fields.append(field)
        if SAME_WAY_RE.search(text):  # "…, then SET for A3, and SET for A4"
            fields += further_like(text, label, field, heading)
    if len(fields) < 2 or pair is None:
        return None
    if len(fields) < len(segments):
        end = ""  # (the walk read stops before its end: no pause read after it)
    said = " ".join(t for _, t in segments)
    return {
        "pair": pair,
        "fields": fields,
        "at": at,
        "timeout": walk_timeout(b, end, at),
        "said": said,
    }


def _segments(
    b: Builder, groups: list[tuple[int, str]], label: str, pairs: list[tuple[list[str], list[str]]]
) -> tuple[list[tuple[str, str]], str]:
    """The walk's fields as (the step opening it, that step with the steps setting it), and
    the step after the last one (how the walk ends). A step setting a field names the pair in
    its first sentence (a worked example run into the last step names it later)."""
    out: list[list[str]] = [[groups[0][1], groups[0][1]]]
    for _, text in groups[1:]:
        if moves_on(text, label):
            out.append([text, text])
        elif pair_of(b, pairs, text.split(". ")[0]) or pair_of(b, pairs, out[-1][1]) is None:
            out[-1][1] = f"{out[-1][1]} {text}"
        else:
            return [(o, t) for o, t in out], text
    return [(o, t) for o, t in out], ""


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
        len(rest) >= 2 and moves_on(rest[0], label) and pair_of(b, pairs, rest[1])
    ):
        return None  # the hours of a clock, or a walk through two settings
    pair = pair_of(b, pairs, first)
    field = read_field(opened, f"{opened} {first}", at) if pair else None
    if pair is not None and field is None and (field := listed_field(b, opened, at)):
        field["label"] = label  # (the display shows the value under the walk's key)
        return _walk(pair, field, at, rest, groups)  # "1515, 1615, … 2288" printed elsewhere
    if pair is None or field is None:
        return None
    own = field_name(opened) or flashing_name(opened)  # ("The bonus flashes": the bonus)
    heading = re.sub(r"\([^)]*\)|\d", " ", b.manual.units[at].heading).lower()
    name = own or "_".join(re.findall(r"[a-z]+", heading)[:3])
    if not name or name in _BARE:
        name = "_".join([*re.findall(r"[a-z]+", label.lower()), name or "setting"])
    field.update(name=name, label=field_label(opened, label))
    timeout = pause_seconds(rest[0]) if rest else None
    said = " ".join(g[1] for g in groups[:2])
    return {
        "pair": pair,
        "fields": [field],
        "at": at,
        "timeout": timeout,
        "own": bool(own),
        "said": said,
    }


def _walk(
    pair: tuple[list[str], list[str]],
    field: dict[str, Any],
    at: int,
    rest: list[str],
    groups: list[tuple[int, str]],
) -> dict[str, Any]:
    """A one-field walk whose field was read whole (named, its values listed)."""
    return {
        "pair": pair,
        "fields": [field],
        "at": at,
        "timeout": pause_seconds(rest[0]) if rest else None,
        "own": True,
        "said": " ".join(g[1] for g in groups[:2]),
        "listed": True,
    }


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
            controls = controls_of(b, action)
            for info in b.infos:
                if held and info.skill == "hold" and info.controls == controls:
                    holds[info.name] = held if k == 0 else -held
    last = groups[4][1] if len(groups) > 4 else ""
    confirm = moves_on(last, label)
    timeout = None if confirm else pause_seconds(last)
    return {
        "pair": pair,
        "clock": field_label(opened, label),
        "name": field_name(opened),  # "AL and the alarm time appear": the alarm time
        "minute": minute,
        "holds": holds,
        "confirm": confirm,
        "at": at,
        "timeout": timeout,
    }
