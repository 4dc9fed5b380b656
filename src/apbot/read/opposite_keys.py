"""Two keys whose legends are opposite verbs: one setting, each key choosing its own state.

An autopilot's AUTO and STANDBY, an alarm's ARM and DISARM, a door's LOCK and UNLOCK: each key
puts the appliance in its own state, and the legend says so with a verb and its negation ("AUTO
– engage the pilot", "STANDBY – disengage, steer by hand"). Read key by key, one was guessed a
power switch (STANDBY) and the other a setting of its own, so neither state could be asked
for. Read here: a legend line per key (the label, a dash or colon, a verb), the second verb the
first with "dis" or "un" before it. The two keys become one setting, valued by the two labels
(the state the manual says the appliance starts in first), each key's press choosing its own.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.value_keys import drop_key_roles

_REFUSED_RE = re.compile(
    r"\b(?:do(?:es)?\s+not|don't|doesn't|cannot|can't)\s+(?:alter|change|work|move|set)\b"
    r"|\bare\s+(?:refused|ignored|locked|disabled)\b",
    re.I,
)
_STARTS_RE = r"\bstarts?\s+(?:up\s+)?in\s+(?:the\s+)?{label}\b"


def _verb(b: Builder, label: str) -> tuple[str, int] | None:
    """The first verb of the key's legend line ("AUTO – engage the pilot": engage)."""
    pattern = re.compile(rf"^{re.escape(label)}\s*(?:[–—:-]|\s{{2,}})\s*(?:to\s+)?([a-z]{{3,}})\b")
    for at, unit in enumerate(b.manual.units):
        m = pattern.match(unit.text.strip())
        if m:
            return m.group(1).lower(), at
    return None


def read_opposite_keys(b: Builder) -> None:
    """Make each pair of keys with opposite legend verbs one setting of two states."""
    keys = []
    for info in b.infos:
        lab = b.labels.get(info.controls[0]) if len(info.controls) == 1 else None
        if info.skill == "press" and lab is not None and lab.line is not None:
            verb = _verb(b, lab.text)
            if verb is not None:
                keys.append((info.name, lab.text, *verb))
    for on, on_label, on_verb, at in keys:
        for off, off_label, off_verb, _ in keys:
            if off_verb not in (f"dis{on_verb}", f"un{on_verb}"):
                continue
            text = " ".join(u.text for u in b.manual.units)
            states = [off_label, on_label]
            if re.search(_STARTS_RE.format(label=re.escape(on_label)), text) and not re.search(
                _STARTS_RE.format(label=re.escape(off_label)), text
            ):
                states.reverse()
            drop_key_roles(b, {on, off})
            values = [s.lower() for s in states]
            var = b.add_discrete("mode", values, "MODE", None)
            b.variables[var]["wrap"] = False
            b.feature(
                var,
                [
                    {"actions": [on], "variable": var, "effect": {"to": on_label.lower()}},
                ],
            )
            b.feature(
                f"{var}_{off_label.lower()}",
                [{"actions": [off], "variable": var, "effect": {"to": off_label.lower()}}],
            )
            b.note(f"variables.{var}", f"{on_label} and {off_label}: opposite states", at)
            _refused_in(b, var, off_label)
            return


def _refused_in(b: Builder, mode: str, label: str) -> None:
    """The keys of a setting the manual says are refused in one state ("In STANDBY these keys
    do not alter the course; the pilot sounds a short beep"): a guard, so that the plan leaves
    the state before it uses them."""
    refused: set[str] = set()
    for at, unit in enumerate(b.manual.units):
        if not re.match(rf"^in\s+{re.escape(label)}\b", unit.text, re.I):
            continue
        if not _REFUSED_RE.search(unit.text):
            continue
        for var in b.variables:
            if var == mode or not re.search(rf"\b{re.escape(var.replace('_', ' '))}\b", unit.text):
                continue
            for steps in b.features.values():
                if steps and steps[-1].get("variable") == var and len(steps) == 1:
                    refused |= set(steps[0].get("actions") or [])
        if refused:
            allowed = [i.name for i in b.infos if i.name not in refused]
            b.guards.append({"name": label.lower(), "when": {mode: label.lower()}, "only": allowed})
            b.note(
                f"guards.{label.lower()}",
                f"in {label} the keys of {sorted(refused)} are refused",
                at,
            )
            return
