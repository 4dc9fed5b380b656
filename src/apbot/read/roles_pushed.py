"""A push-and-turn knob that sets its own amount: pushed, it opens the setting its label
names; its own turns then change it (kept apart from roles_amounts, which hands the panel's
shared stepping pair and dials to the entry keys)."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.pushed_parts import pushed_part_toggle, pushed_toggle
from apbot.read.roles_common import label_of, mentions_of, numeric_list, turns, var_name
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
        pushed = pushed_part_toggle(b, key)
        if pushed:  # "TEMP  turn: set point; push: heating on / off": the push is that toggle
            pushed_toggle(b, key, pushed)
            continue
        if push_runs(b, token):
            _push_toggles_run(b, key)  # "Push to start or pause.": the turns alone set it
            continue
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


def _push_toggles_run(b: Builder, key: ActionInfo) -> None:
    """The knob's push starts and pauses the appliance: a toggle of its running state (the one
    START already reads, else a new one the display is not said to show)."""
    var = next((n for n, v in b.variables.items() if v.get("label") == "RUN"), None)
    if var is None:
        var = b.unique("running", b.variables)
        b.variables[var] = {"type": "discrete", "values": ["off", "on"], "label": "RUN"}
        b.variables[var]["visible"] = False
    b.feature(f"push_{key.token}", [{"actions": [key.name], "variable": var, "effect": "toggle"}])


# a push clause, up to the end of its sentence: "Push to start or pause", "pressing it confirms"
_PUSH_CLAUSE = re.compile(r"\b(?:push|press)(?:es|ed|ing)?\b[^.;]*", re.IGNORECASE)
_RUNS = re.compile(
    r"\b(?:start|pause|stop|resume|begin|confirm|cancel)(?:s|ed|ing)?\b", re.IGNORECASE
)
_OPENS = re.compile(
    r"\b(?:open|select|choose|set|adjust|change|flash|blink)(?:s|es|ed|ing)?\b", re.IGNORECASE
)
# a sentence whose subject is still the knob of the one before ("Push to start", "Press it to …")
_BARE_PUSH = re.compile(r"^\W*(?:push|press)(?:ing)?\b(?:\s+(?:it|again|once))?\s*(?:to\b|:)", re.I)


def push_runs(b: Builder, token: str) -> bool:
    """Whether the knob's own legend says its push starts, pauses or confirms ("TIME knob: Turn
    to set the time. Push to start or pause.") and never that the push opens an amount: the
    push is then a key of its own, not the first step of setting the knob's amount."""
    units = b.manual.units
    clauses: list[str] = []
    for i in mentions_of(b, token):
        clauses += _PUSH_CLAUSE.findall(units[i].text)
        for k in range(i + 1, min(i + 3, len(units))):
            if units[k].line != units[i].line and not _BARE_PUSH.match(units[k].text):
                break
            clauses += _PUSH_CLAUSE.findall(units[k].text)
    if any(_OPENS.search(c) for c in clauses):
        return False
    return any(_RUNS.search(c) for c in clauses)
