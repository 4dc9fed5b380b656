"""Dials with values of their own, and the guess for keys nothing else explained.

These run after the amounts (:mod:`apbot.read.roles_amounts`) have taken the keys that set an
entry, so what is left is either a dial the manual charts or a key the manual is unclear about,
guessed as the setting the closed loop repairs most cheaply.
"""

from __future__ import annotations

from dataclasses import replace

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.pressed_names import pressed_names
from apbot.read.roles_common import NUMERIC_WORDS, label_of, numeric_list, turns, var_name
from apbot.read.roles_confirm import confirmed_noun, ends_entry
from apbot.read.roles_lists import dial_ends, list_evidence
from apbot.read.shapes import CHOICE_WORDS, Evidence


def others_choices(b: Builder, values: list[str]) -> bool:
    """The list is the choices of a setting already read (\"MMA, TIG, MIG\" of PROCESS, drawn
    beside the AMPS knob): a dial that also has a range sets that amount, not those choices."""
    mine = {str(v).lower() for v in values}
    return any(
        spec.get("type") == "discrete"
        and {str(v).lower() for v in spec.get("values") or []} == mine
        for spec in b.variables.values()
    )


def assign_dials(
    b: Builder, dials: dict[str, list[ActionInfo]], silent: list[ActionInfo]
) -> list[ActionInfo]:
    """Dials with their own values (a generic dial already taken as a stepper is skipped), and
    a key pressed before turning its dial; returns the keys still without a role."""
    for token, moves in dials.items():
        cw, ccw = turns(moves)
        used = {a for steps in b.features.values() for st in steps for a in st["actions"]}
        if set(cw + ccw) & used:
            continue
        ev = b.evidence([token])
        lab = label_of(b, token)
        if ev.values and ev.ranges and others_choices(b, ev.values):
            ev = replace(ev, values=None, values_at=None)  # AMPS beside the process lamps
        if ev.values and not numeric_list(ev.values):
            var = b.add_discrete(token, ev.values, lab, ev)
            b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), ev.values_at)
        elif ev.values:
            var = b.add_number(token, lab, list_evidence(ev), cyclic=False)
        else:
            var = b.add_number(token, lab, ev, cyclic=False)
        eff = {**{a: "next" for a in cw}, **{a: "prev" for a in ccw}}
        b.feature(f"select_{var}", [{"actions": cw + ccw, "variable": var, "effect": eff}])
        dial_ends(b, token, var)
        values = b.variables[var].get("values") or []
        if (
            values
            and values[0] == "off"
            and "power" not in b.variables
            and not any(g["name"] == "power off" for g in b.guards)
        ):  # a knob whose first position is OFF is the on/off switch: off, nothing else works
            b.guards.append(
                {"name": "power off", "when": {var: "off"}, "only": cw + ccw, "display": "",
                 "hide": True}
            )  # fmt: skip
            b.note("guards.power off", f"the {lab} knob at OFF switches the appliance off")
        for k in [k for k in silent if k.token == token]:
            b.feature(
                f"{k.token}_press",
                [{"actions": [k.name]}, {"actions": cw + ccw, "variable": var, "effect": eff}],
            )
            silent.remove(k)
    return silent


def assign_leftovers(b: Builder, silent: list[ActionInfo], evidence: dict[str, Evidence]) -> None:
    """Whatever is left: an amount a key steps, or a toggle the closed loop can repair."""
    digit_keys = {i.name for i in b.infos if i.digit is not None}
    typed = [  # the features whose last step the number keys type
        name
        for name, steps in b.features.items()
        if steps and set(steps[-1].get("actions") or []) & digit_keys and steps[-1].get("variable")
    ]
    for key in silent:
        if typed and key.skill == "press" and ends_entry(b, key) and not confirmed_noun(b, key):
            # "Press ENTER to finish": the last step of what the number keys type, no setting
            # ("ENTER  Ends the entry of a design number" names its own setting instead)
            for name in _entries_closed(b, key, typed):
                b.features[name].append({"actions": [key.name], "note": "closes the entry"})
                b.note(f"features.{name}", f"{key.name} closes the entry")
            continue
        name = var_name(b, key)
        ev = evidence.get(key.name)
        own = {i for c in key.controls if c in b.labels for i in b.labels[c].mentions}
        stepped = (  # "press WASH, RINSE or SPIN: every press gives the next value"
            ev is not None
            and ev.each_press_at in own
            and ev.toggle_at is None
            and not set(words(name)) & CHOICE_WORDS
        )
        if (set(words(name)) & NUMERIC_WORDS or stepped) and key.skill == "press":
            var = b.add_number(name, label_of(b, key.controls[0]), evidence[key.name], cyclic=True)
            b.feature(f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}])
            b.note(f"features.set_{var}", f"{key.name} steps an amount (the manual says no more)")
            continue
        counted = pressed_names(b.manual.units, name, label_of(b, key.controls[0]))
        if counted and key.skill == "press":  # "| Press | … | Pattern |": what each press picks
            var = b.add_discrete(name, counted[0], label_of(b, key.controls[0]), None)
            b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), counted[1])
            b.feature(f"set_{var}", [{"actions": [key.name], "variable": var, "effect": "next"}])
            continue
        var = b.add_toggle(name, label_of(b, key.controls[0]), None)
        b.feature(var, [{"actions": [key.name], "variable": var, "effect": "toggle"}])
        b.note(
            f"features.{var}",
            f"{key.name} toggles a setting of its own (the manual says nothing clear)",
        )


def _entries_closed(b: Builder, key: ActionInfo, typed: list[str]) -> list[str]:
    """The typed entries the closing key ends: at each mention of the closing key, the entry
    whose opening key the manual named last, a few units before (its own steps); all of them
    when none is (review31: "3. Press ENTER to finish" in the code's steps does not close the
    clock's entry)."""
    starts: dict[str, set[int]] = {}
    for name in typed:
        steps = b.features[name]
        opening = [i for i in b.infos if i.name in (steps[0].get("actions") or [])]
        if len(steps) >= 2 and len(opening) == 1 and not steps[0].get("variable"):
            starts[name] = {
                i for c in opening[0].controls if c in b.labels for i in b.labels[c].mentions
            }
    near: list[str] = []
    for end in (i for c in key.controls if c in b.labels for i in b.labels[c].mentions):
        before = {
            n: max(s)
            for n, at in starts.items()
            if (s := [i for i in at if 0 <= end - i <= _STEPS])
        }
        if before:
            last = max(before, key=lambda n: before[n])
            if last not in near:
                near.append(last)
    return near or typed


_STEPS = 6  # units from an entry's opening key to its closing step
