"""Keys that work only while a switch is on: "▲ and ▼ only work while heating is on".

Manuals often say that a setting's keys do nothing until an on/off setting is switched on —
the heater for a set temperature: "▲ and ▼ only work while heating is on", a key legend's
"Raises the set bath temperature (heater on only)", "With the heater off ▲ and ▼ have no
effect". Read without it, the planner presses ▲ before HEAT, the presses are refused and the
belief drifts from the appliance; and a user asking for "60 degrees" never gets the heater on.
A guard refusing those keys while the switch is off makes the planner switch it on first.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import mentions_of

_SKIP = frozenset({"power", "running", "child_lock"})  # (guarded on their own)
_REFUSED = (
    r"no\s+effect|do(?:es)?\s+nothing|do(?:es)?\s+not\s+(?:change|react|work|respond)"
    r"|(?:is|are)\s+ignored"
)


def _conditions(stem: str) -> list[re.Pattern[str]]:
    """The ways a sentence makes keys work only while the switch named by ``stem`` is on."""
    w = rf"(?:the\s+)?{re.escape(stem)}\w*"
    return [
        # "▲ and ▼ only work while heating is on"
        re.compile(
            rf"\bonly\s+(?:works?|reacts?|responds?|functions?)\s+(?:while|when|if)\s+{w}\s+"
            rf"(?:is|are)\s+(?:switched\s+|turned\s+)?on\b",
            re.I,
        ),
        # a key legend's "(heater on only)"
        re.compile(rf"\(\s*{w}\s+on\s+only\s*\)", re.I),
        # "With the heater off ▲ and ▼ have no effect" (in one clause: not "…, TIMER still
        # counts down but the plate does not change")
        re.compile(
            rf"\b(?:with|while|when|if)\s+{w}\s+(?:is\s+|are\s+)?(?:switched\s+)?off\b"
            rf"(?:(?!\bbut\b)[^.;]){{0,80}}\b(?:{_REFUSED})\b",
            re.I,
        ),
    ]


def _switches(b: Builder) -> dict[str, list[str]]:
    """Each on/off setting a key toggles, with the word stems it is named by (HEAT: heat)."""
    toggled = {
        str(s.get("variable"))
        for steps in b.features.values()
        for s in steps
        if s.get("effect") == "toggle"
    }
    out: dict[str, list[str]] = {}
    for var, spec in b.variables.items():
        if var in _SKIP or var not in toggled or "cases" in spec:
            continue
        if sorted(str(v) for v in spec.get("values") or []) != ["off", "on"]:
            continue
        stems = [w for w in words(str(spec.get("label") or "")) if len(w) >= 3 and w.isalpha()]
        if stems:
            out[var] = stems
    return out


def _setting_actions(b: Builder, switch: str) -> dict[str, set[str]]:
    """The pressed actions that set another setting, each with its keys' tokens."""
    out: dict[str, set[str]] = {}
    for steps in b.features.values():
        for step in steps:
            var = str(step.get("variable"))
            if var == switch or var in _SKIP or var not in b.variables:
                continue
            for name in step.get("actions") or []:
                info = next((i for i in b.infos if i.name == name), None)
                if info is not None and info.skill == "press" and info.digit is None:
                    out[name] = set(info.controls)
    return out


_CLAUSE_END = re.compile(r"[.;:]\s|\bbut\b", re.I)


def _clause(text: str, match: re.Match[str]) -> str:
    """The clause a condition stands in, from the clause's start up to the condition's end:
    the keys it names ("+ and - only work while warming is on"), not those of the next
    clause ("; TIMER works at any time")."""
    start = max((m.end() for m in _CLAUSE_END.finditer(text, 0, match.start())), default=0)
    return text[start : match.end()]


def _said_elsewhere(label: str, text: str, clauses: list[str]) -> bool:
    """The key's printed label stands in the sentence, but in none of the condition's clauses."""
    if not label:
        return False
    printed = re.compile(rf"(?<![A-Za-z0-9]){re.escape(label)}(?![A-Za-z0-9])")
    return bool(printed.search(text)) and not any(printed.search(c) for c in clauses)


def read_enabling_switches(b: Builder) -> None:
    """Guard a setting's keys with the switch the manual says they need switched on."""
    for switch, stems in _switches(b).items():
        if any(switch in g["when"] for g in b.guards):
            continue
        own = {
            t
            for steps in b.features.values()
            for s in steps
            if s.get("variable") == switch
            for a in s.get("actions") or []
            for i in b.infos
            if i.name == a
            for t in i.controls
        }
        actions = _setting_actions(b, switch)
        refused: set[str] = set()
        at: int | None = None
        patterns = [p for stem in stems for p in _conditions(stem)]
        for index, unit in enumerate(b.manual.units):
            clauses = [_clause(unit.text, m) for p in patterns for m in p.finditer(unit.text)]
            if not clauses:
                continue
            named = {
                t
                for t in b.labels
                if t not in own
                and index in mentions_of(b, t)
                and not _said_elsewhere(b.labels[t].text, unit.text, clauses)
            }
            hit = {a for a, tokens in actions.items() if tokens and tokens <= named}
            if hit:
                refused |= hit
                at = index if at is None else at
        if not refused:
            continue
        b.guards.append(
            {
                "name": f"{switch} off",
                "when": {switch: "off"},
                "only": [i.name for i in b.infos if i.name not in refused],
                "display": "",
            }
        )
        keys = ", ".join(sorted(refused))
        b.note(f"guards.{switch} off", f"{keys} work only while {switch} is on", at)
