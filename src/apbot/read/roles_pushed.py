"""A push-and-turn knob that sets its own amount: pushed, it opens the setting its label
names; its own turns then change it (kept apart from roles_amounts, which hands the panel's
shared stepping pair and dials to the entry keys)."""

from __future__ import annotations

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import label_of, numeric_list, turns, var_name
from apbot.read.roles_lists import list_evidence
from apbot.read.shapes import CHOICE_WORDS, Evidence


def pushed_dials(
    b: Builder,
    entry_keys: list[ActionInfo],
    evidence: dict[str, Evidence],
    dials: dict[str, list[ActionInfo]],
    generic_dials: list[str],
    steppers: list[tuple[list[str], list[str]]],
) -> list[ActionInfo]:
    """A push-and-turn knob whose push opens an amount ("Push the TIME knob: the time flashes;
    turn it to change the time"): the push, then the knob's own turns, set it, not a stepping
    pair elsewhere on the panel (unless the knob is the only way the other entry keys have to
    set theirs). Its turns leave ``steppers``; returns the entry keys left."""
    left: list[ActionInfo] = []
    for key in entry_keys:
        token = key.controls[0]
        if key.skill != "press" or len(key.controls) != 1 or token not in dials:
            left.append(key)
            continue
        cw, ccw = turns(dials[token])
        others = [k for k in entry_keys if k is not key]
        if not (cw and ccw) or (others and [(cw, ccw)] == steppers):
            left.append(key)  # (the knob is also how the other keys' amounts are set)
            continue
        if (cw, ccw) in steppers:
            steppers.remove((cw, ccw))
        ev = evidence[key.name]
        if ev.values and len(ev.values) >= 3 and numeric_list(ev.values):
            ev = list_evidence(ev)
        name, lab = var_name(b, key), label_of(b, token)
        named = [w for w in words(lab) if w not in CHOICE_WORDS]
        if set(words(name)) & CHOICE_WORDS and named:
            name = "_".join(named)  # the knob printed TIME sets a time, not a "knob"
        var = b.add_number(name, lab, ev, cyclic=False)
        eff = {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}}
        b.feature(
            f"set_{var}",
            [{"actions": [key.name]}, {"actions": cw + ccw, "variable": var, "effect": eff}],
        )
        b.note(f"features.set_{var}", f"{key.name} then the knob's own turns", ev.range_at)
    return left
