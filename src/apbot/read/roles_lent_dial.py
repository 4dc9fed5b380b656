"""A key that lends a named dial to a setting of its own: "1. Press BASS. 2. Turn the VOLUME
knob: from −6 dB to +6 dB".

A dial printed with its own name (VOLUME, TEMP) keeps its own setting, so the rules that give
entry keys a shared adjuster (the unnamed ▲ / ▼ pair, a dial called DIAL or SELECT) pass it by,
and a key whose only sentences are such a procedure is left with no role (or grouped with its
neighbours as one choice). A press key whose step is followed, in the same section, by a step
that turns the named dial and states a range is an entry key of that dial: a setting of its
own, named after the key, set by the dial's turns after pressing it. A later step of the same
procedure that presses another key "in the same way" lends it the dial with the same range
("3. Press TREBLE to adjust the treble in the same way").
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_common import label_of, mentions_of, turns, var_name
from apbot.read.shapes import Evidence
from apbot.read.value_steps import find_step
from apbot.read.values import UNIT, Range, find_ranges, unit_name
from apbot.read.values_signed import signed_spans

_SAME_WAY_RE = re.compile(r"\b(?:in the same way|the same way|likewise|as above)\b", re.I)


def _turn_step(b: Builder, i: int, dial: str) -> int | None:
    """The unit that turns ``dial`` right after unit ``i``: the rest of its own sentence ("press
    BASS, then turn VOLUME"), else the next numbered step of the section (or, in prose, one of
    the next two sentences) when it starts by turning the dial."""
    units = b.manual.units
    name = re.escape(label_of(b, dial))
    turn = rf"(?:turn|rotate)\w*\s+(?:the\s+)?{name}(?!\w)"
    if re.search(rf"\bthen\s+{turn}", units[i].text, re.I):
        return i
    turned = re.compile(rf"^\W*(?:\d+[.)]\s*)?(?:then\s+)?{turn}", re.I)
    stepped = units[i].step is not None
    for j in range(i + 1, min(i + (6 if stepped else 3), len(units))):
        if units[j].heading != units[i].heading or units[j].cells:
            return None
        if stepped and units[j].step is None:
            continue  # the step's further sentences ("The display shows BASS 0 dB.")
        return j if turned.search(units[j].text) else None
    return None


def _ranges(text: str) -> list[Range]:
    """The range a turn step states, unsigned or reaching below zero ("−6 dB to +6 dB")."""
    found = find_ranges(text)
    if found:
        return found
    return [
        Range(low, high, "dB" if said.lower() == "db" else unit_name(said))
        for low, high, said in signed_spans(text, UNIT)
    ]


def _pressed(b: Builder, key: ActionInfo) -> re.Pattern[str]:
    label = re.escape(label_of(b, key.controls[0]))
    return re.compile(
        rf"^\W*(?:\d+[.)]\s*)?(?:press|touch|push)\w*\s+(?:the\s+)?{label}(?!\w)", re.I
    )


Lent = tuple[ActionInfo, str, int, int]  # the key, the dial, the key's step, the turn step


def lent_dial_keys(
    b: Builder, keys: list[ActionInfo], dials: dict[str, list[ActionInfo]]
) -> list[Lent]:
    """The press keys in ``keys`` that a step hands a named dial: each with the dial, the unit
    pressing it and the unit turning the dial (their settings are added by :func:`add_lent`,
    once the dial has its own)."""
    units = b.manual.units
    found: list[Lent] = []
    for dial, actions in dials.items():
        cw, ccw = turns(actions)
        if not (cw and ccw) or dial not in b.labels:
            continue
        lent: dict[str, Lent] = {}
        taken = {k.name for k, *_ in found}
        for key in keys:
            if key.skill != "press" or key.name in taken or key.controls[0] not in b.labels:
                continue
            pressed = _pressed(b, key)
            for i in mentions_of(b, key.controls[0]):
                if not pressed.search(units[i].text):
                    continue
                j = _turn_step(b, i, dial)
                if j is not None and _ranges(units[j].text):
                    lent[key.name] = (key, dial, i, j)
                    break
        for key in keys:  # "3. Press TREBLE to adjust the treble in the same way"
            if key.skill != "press" or key.name in lent or key.name in taken or not lent:
                continue
            if key.controls[0] not in b.labels:
                continue
            pressed = _pressed(b, key)
            for i in mentions_of(b, key.controls[0]):
                text = units[i].text
                if not (pressed.search(text) and _SAME_WAY_RE.search(text)):
                    continue
                heading = units[i].heading
                before = [v for v in lent.values() if v[3] < i and units[v[2]].heading == heading]
                if before:
                    lent[key.name] = (key, dial, i, before[-1][3])
                    break
        found += lent.values()
    return found


def add_lent(b: Builder, found: list[Lent], dials: dict[str, list[ActionInfo]]) -> list[ActionInfo]:
    """A setting per key of ``found``, named after it, its range read in the turn step, set by
    pressing the key and then turning the dial; returns the keys not lent the dial (left for
    the other roles)."""
    left: list[ActionInfo] = []
    for key, dial, i, j in found:
        cw, ccw = turns(dials[dial])
        if _own_range_unread(b, cw + ccw):
            # "1. Press BT. 2. Turn the VOLUME knob to a comfortable level (0 to 30).": the
            # manual gives the dial no range of its own, so the range is the dial's own one
            left.append(key)
            continue
        text = b.manual.units[j].text
        ev = Evidence(ranges=_ranges(text), range_at=j)
        step = find_step(text)
        if step is not None:
            ev.step, ev.step_at = step, j
        var = b.add_number(var_name(b, key), label_of(b, key.controls[0]), ev, cyclic=False)
        b.feature(
            f"set_{var}",
            [
                {"actions": [key.name]},
                {
                    "actions": cw + ccw,
                    "variable": var,
                    "effect": {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}},
                },
            ],
        )
        b.note(f"features.set_{var}", f"{key.name} then the {dial} dial's turns", i)
    return left


def _own_range_unread(b: Builder, turned: list[str]) -> bool:
    """The dial's own numeric setting (the one its turns alone set) got no range from the
    manual (its range is a guess)."""
    own = {
        st.get("variable")
        for steps in b.features.values()
        if len(steps) == 1
        for st in steps
        if set(st.get("actions", [])) == set(turned)
    }
    return any(v in b.unread for v in own if v)
