"""Keys locked while the appliance runs, named by the sign it shows: "While FRY is shown, MENU
and AUTO LIFT are locked: pressing them shows BUSY."

A manual says which keys stop working during a run by naming them, and the run by the word
on the display. Without that guard a belief may start first and choose a programme after,
which the panel refuses. The guard refuses just the named keys (the rest still work: the
manual went to the trouble of naming the locked ones), with the refusal's word if it gives one.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.range_codes import _actions_said

_LOCKED = re.compile(
    r"\b(?:are|is)\s+(?:locked|ignored|refused|disabled|blocked)\b|\b(?:do|does)\s+(?:not\s+work|"
    r"nothing)\b|\bhave\s+no\s+effect\b",
    re.IGNORECASE,
)
# the refusal's own word: "pressing them shows BUSY", "the display shows Err"
_REFUSAL = re.compile(r"\bshows?\s+([A-Z][A-Za-z0-9-]{1,7})\b")


def read_running_locks(b: Builder) -> None:
    """Guard the keys a sentence says are locked while the running word is shown."""
    spec = b.variables.get("running")
    word = (spec or {}).get("show", {}).get("on") if spec else None
    if not word or any(g.get("when") == {"running": "on"} for g in b.guards):
        return
    shown = re.compile(
        rf"\b(?:while|when|as\s+long\s+as)\s+{re.escape(word)}\s+is\s+(?:shown|lit|displayed|on)\b",
        re.IGNORECASE,
    )
    for at, unit in enumerate(b.manual.units):
        m = shown.search(unit.text)
        rest = unit.text[m.end() :] if m else ""
        locked = _LOCKED.search(rest)
        if not m or not locked:
            continue
        keys = _actions_said(b, rest[: locked.start()])
        if not keys or keys & _actions_of_running(b):
            continue
        only = [i.name for i in b.infos if i.name not in keys]
        refusal = _REFUSAL.search(rest[locked.end() :])
        b.guards.append(
            {
                "name": "running",
                "when": {"running": "on"},
                "only": only,
                "display": refusal.group(1) if refusal else "",
            }
        )
        b.note("guards.running", f"{', '.join(sorted(keys))} locked while {word} is shown", at)
        return


def _actions_of_running(b: Builder) -> set[str]:
    """The actions that start or stop the run (never among the locked ones)."""
    return {
        a
        for steps in b.features.values()
        for step in steps
        if step.get("variable") == "running"
        for a in step.get("actions") or []
    }
