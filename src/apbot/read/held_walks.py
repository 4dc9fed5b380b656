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
from apbot.read.code_words import own_lines
from apbot.read.held_guesses import drop_guess, drop_key_guesses, says
from apbot.read.roles_fasthold import held_time_step
from apbot.read.value_steps import find_step
from apbot.read.values import find_ranges
from apbot.read.walk_fields import (
    SAME_WAY_RE,
    code_words,
    field_label,
    field_name,
    like,
    read_field,
    read_more_field,
)
from apbot.read.walk_flashed import (
    clock_effects,
    clock_field,
    clock_steps,
    flashed_field,
    held_steps,
    joined_clocks,
    name_by_flashing,
    table_field,
)
from apbot.read.walk_known import known_field, use_known
from apbot.read.walk_like import (
    absorb_pair_setting,
    drop_opener_setting,
    further_like,
    named_by_code,
    squeezed_arrows,
)
from apbot.read.walk_order import read_coded_field, with_step
from apbot.read.walk_steps import (
    adjusts,
    drop_adjuster_settings,
    moves_at_ends,
    prose_opener,
    single_keys,
    walk_steps,
)

# a field's name that says nothing of what it is: its key's name leads it ("snooze length")
_BARE = frozenset({"length", "duration", "time", "setting", "value", "level"})
# "Do not touch any key for 5 seconds: the setting is stored", "stored after a few seconds"
_STORED_RE = re.compile(
    r"\b(?:for|after|wait)\s+(?:(\d+)|a few)\s+seconds?\b[^.]*|\bstored\b[^.]*\bseconds\b", re.I
)
# a key held for those seconds is no pause: "Press and hold MODE for 2 seconds to save",
# "hold MODE for 2 seconds; the display returns to …", "keep SET pressed for 3 seconds"
_HELD_FOR_RE = re.compile(r"\b(?:hold|holding|held|keep\s+\S+\s+pressed)\b[^.;:]*$", re.I)
# a step the walk may pass over: "To keep it unchanged, go straight to step 3."
_SKIP_RE = re.compile(
    r"\bgo\s+(?:straight|directly)\s+(?:on\s+)?to\s+step\b|\bskip\s+(?:this|the)\s+step\b", re.I
)
# what a pause does at the end of a walk: "If you press no key for 8 seconds, the menu closes"
_CLOSES_RE = re.compile(r"\b(?:closes?|stored|returns?|leaves?|exits?)\b", re.I)
# a dial named by its kind rather than its label: "Turn the knob to choose …"
_TURN_RE = re.compile(r"\bturn\s+the\s+(?:\w+\s+)?(?:knob|dial|wheel|ring|selector)\b", re.I)
_CLOCK_FIELDS_RE = re.compile(r"\bhours?\b[^.]*\bflash", re.I)
_HOURS_RE = re.compile(r"\bhours?\b", re.I)
_MINUTES_RE = re.compile(r"\bminutes?\b", re.I)


def _pause(text: str) -> float | None:
    """The seconds of a pause without a key after which the walk ends ("Do not touch any key
    for 5 seconds: the setting is stored"), not a key held that long."""
    for m in _STORED_RE.finditer(text):
        if not _HELD_FOR_RE.search(text[: m.start()]):
            return float(m.group(1) or 5)
    return None


def _pairs(b: Builder) -> list[tuple[list[str], list[str]]]:
    """The stepping pairs the model already has: presses (or a dial's two turns) that step one
    setting up and down."""
    press = {i.name for i in b.infos if i.skill == "press" or i.skill.startswith("turn")}
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


def read_held_walks(b: Builder) -> None:
    """Replace a held key's guessed switch by the two settings its numbered steps walk."""
    units = b.manual.units
    pairs = _pairs(b)
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
    """Two or more settings the held key's steps walk: the hold opens the first, each short
    press of the key the next, and the pair sets each."""
    groups = moves_at_ends(groups, label)
    if len(groups) < 3:
        return None
    if _CLOCK_FIELDS_RE.search(groups[0][1]):  # the hours, then the minutes, of one clock
        if len(groups) < 4 or not _moves_on(groups[2][1], label):
            return None
        pair = _pair_of(b, pairs, groups[1][1])
        if pair is None or _pair_of(b, pairs, groups[3][1]) != pair:
            return None
        return _clock_walk(b, groups, label, pair, at)
    segments, end = _segments(b, groups, label, pairs)
    segments, clocks = joined_clocks(segments)
    fields: list[dict[str, Any]] = []
    pair = None
    heading = b.manual.units[at].heading
    for opened, text in segments:
        own = _pair_of(b, pairs, text) or (pair if fields and SAME_WAY_RE.search(text) else None)
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
    return {"pair": pair, "fields": fields, "at": at, "timeout": _timeout(b, end, at), "said": said}


def _segments(
    b: Builder, groups: list[tuple[int, str]], label: str, pairs: list[tuple[list[str], list[str]]]
) -> tuple[list[tuple[str, str]], str]:
    """The walk's fields as (the step opening it, that step with the steps setting it), and
    the step after the last one (how the walk ends). A step setting a field names the pair in
    its first sentence (a worked example run into the last step names it later)."""
    out: list[list[str]] = [[groups[0][1], groups[0][1]]]
    for _, text in groups[1:]:
        if _moves_on(text, label):
            out.append([text, text])
        elif _pair_of(b, pairs, text.split(". ")[0]) or _pair_of(b, pairs, out[-1][1]) is None:
            out[-1][1] = f"{out[-1][1]} {text}"
        else:
            return [(o, t) for o, t in out], text
    return [(o, t) for o, t in out], ""


def _timeout(b: Builder, end: str, at: int) -> float | None:
    """The pause after which the walk ends by itself: said in its last step ("Wait 10 seconds
    without touching a key"), else in a note of its section ("If you press no key for 8
    seconds, the menu closes by itself")."""
    pause = _pause(end)
    if pause is not None:
        return pause
    units = b.manual.units
    for u in units[at : at + 25]:
        if u.heading != units[at].heading:
            break
        pause = _pause(u.text)
        if pause is not None and u.step is None and _CLOSES_RE.search(u.text):
            return pause
    return None


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
    field = read_field(opened, f"{opened} {first}", at) if pair else None
    if pair is None or field is None:
        return None
    own = field_name(opened)
    heading = re.sub(r"\([^)]*\)|\d", " ", b.manual.units[at].heading).lower()
    name = own or "_".join(re.findall(r"[a-z]+", heading)[:3])
    if not name or name in _BARE:
        name = "_".join([*re.findall(r"[a-z]+", label.lower()), name or "setting"])
    field.update(name=name, label=field_label(opened, label))
    timeout = _pause(rest[0]) if rest else None
    said = " ".join(g[1] for g in groups[:2])
    return {
        "pair": pair,
        "fields": [field],
        "at": at,
        "timeout": timeout,
        "own": bool(own),
        "said": said,
    }


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
    text = squeezed_arrows(text)  # "A ▲ / A ▼" for the keys labelled A▲ and A▼
    for up, down in pairs:
        ups = [b.labels[t].text for a in up for t in _controls(b, a) if t in b.labels]
        downs = [b.labels[t].text for a in down for t in _controls(b, a) if t in b.labels]
        if any(says(text, x) for x in ups) and any(says(text, x) for x in downs):
            return up, down
        if not down and any(adjusts(text, x) for x in ups):  # "Press MEM until … is right"
            return up, down
    dials = [p for p in pairs if all(_turned(b, a) for a in p[0] + p[1])]
    if len(dials) == 1 and _TURN_RE.search(text):  # "Turn the knob to choose …"
        return dials[0]
    return None


def _turned(b: Builder, action: str) -> bool:
    return any(i.name == action and i.skill.startswith("turn") for i in b.infos)


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
    timeout = None if confirm else _pause(last)
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


def _controls(b: Builder, action: str) -> tuple[str, ...]:
    return next((i.controls for i in b.infos if i.name == action), ())


def _apply(
    b: Builder, hold: str, press: str | None, walk: dict[str, Any], named: bool = True
) -> None:
    """Drop the hold's guessed setting; add the two fields and the feature walking them (named
    after what the hold was read to set, "sleep_period", when that was more than the key's name
    and "hold"; not when ``named`` is false: a short press opening the walk was a mere guess)."""
    if "clock" in walk:
        _apply_clock(b, hold, press, walk)
        return
    prefix = drop_guess(b, hold) if named else (drop_guess(b, hold) and "")
    if len(walk["fields"]) == 1:  # one setting: the name the hold was read with, else its own
        field = walk["fields"][0]
        field["name"] = field["name"] if walk.get("own") or not prefix else prefix[:-1]
        prefix = ""
    up, down = walk["pair"]
    effect = {**{a: "next" for a in up}, **{a: "prev" for a in down}}
    steps: list[dict[str, Any]] = [{"actions": [hold]}]
    names = []
    for k, field in enumerate(walk["fields"]):
        if field.get("known"):  # "The temperature flashes": the one read from the chart
            var = use_known(b, field["name"], set(up + down))
        elif "spec" in field:
            var = b.unique(_prefix(prefix, field) + field["name"], b.variables)
            b.variables[var] = {"label": field["label"], **field["spec"]}
            b.note(f"variables.{var}", "a time of day the held key's steps set", walk["at"])
        elif "values" in field:
            var = b.add_discrete(
                _prefix(prefix, field) + field["name"], field["values"], field["label"], None
            )
            glossed = code_words(own_lines(b), field["values"])
            if glossed:  # "r1 near – r2 middle – r3 far": the words, the codes shown
                b.variables[var]["values"] = [glossed[c] for c in field["values"]]
                b.variables[var]["show"] = {w: c for c, w in glossed.items()}
            if field.get("show"):  # "(M = male, F = female)": the words, the codes shown
                b.variables[var]["show"] = dict(field["show"])
            if field.get("stops"):
                b.variables[var]["wrap"] = False
            b.note(f"variables.{var}", "the values the held key's walk steps through", walk["at"])
        else:
            var = b.add_number(
                _prefix(prefix, field) + field["name"],
                field["label"],
                field["evidence"],
                cyclic=False,
            )
        if k:
            steps.append({"actions": [press]})
        if field.get("split"):  # the hours, then the minutes, of one time of day
            steps += clock_steps(var, up, down, press, field.get("minute", 60))
        else:
            steps.append({"actions": up + down, "variable": var, "effect": dict(effect)})
        if not down:  # "MEM held 2 s adds ten months"
            held_steps(b, up, steps[-3:] if field.get("split") else steps[-1:], field)
        if field.get("optional") and k < len(walk["fields"]) - 1:
            steps[-1]["optional"] = True  # "to keep it, go straight to step 3"
        names.append(var)
    if walk["timeout"] is not None:  # the walk ends by itself once no key is touched
        for step in steps:
            step["timeout"] = walk["timeout"]
    drop_key_guesses(b, {a for a in (press, *up, *down) if a}, walk["said"])
    feature = f"set_{names[0]}"
    b.feature(feature, steps)
    if not down:  # one key adjusting every field
        drop_adjuster_settings(b, up)
    absorb_pair_setting(b, steps, walk["at"])
    drop_opener_setting(b, steps)
    said = f"{hold} opens {names[0]}" + (f", {press} moves to {names[1]}" if names[1:] else "")
    b.note(f"features.{feature}", said, walk["at"])


def _prefix(prefix: str, field: dict[str, Any]) -> str:
    """A field named by what flashes, or a clock joined from hours and minutes, has a name of
    its own: the hold's guessed name leads it not."""
    return "" if field.get("own_name") or field.get("split") else prefix


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
    drop_guess(b, hold)
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
    hours, minutes = clock_effects(up, down, minute)
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
