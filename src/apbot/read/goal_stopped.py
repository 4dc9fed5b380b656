"""A setting with an OFF value stopped by name: "stop tracking altogether", "stop the
oscillation". The word after "stop" (or "stop the") is the setting's own; the sentence is
written as "tracking off" before it is read — only for a selector of three or more values one
of which is OFF (not an on/off switch: "stop the turning" may switch a LOCKDOWN on; not the
power or the running state, whose stop the start rules read), and only when no number follows
(a "stop at 5" is a value), not when it is said not to ("don't stop tracking") or later ("stop
tracking after ten minutes": a timer's end, not now).
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.read.goal_view import Model, own_stems
from apbot.read.goal_vocab import stem

_SAID = re.compile(
    # (not "don't stop tracking", "never stop the turning": keep it)
    r"(?<!n't\s)(?<!n’t\s)(?<!not\s)(?<!never\s)"
    r"\b(?:stop|cease|quit)\s+(?:the\s+|its\s+)?([A-Za-z]{4,})\b"
    # (not "stop at 5": a value; not "stop tracking after ten minutes": a timer's, later)
    r"(?!\s+(?:at|on|to|by|after|in|\d))",
    re.IGNORECASE,
)


def said_stopped(view: Model, instruction: str) -> str:
    """ "stop tracking" as "tracking off" where TRACKING has an OFF value."""

    def stopped(m: re.Match[str]) -> str:
        key = stem(m[1].casefold())
        named = [
            name
            for name, info in view.infos.items()
            if info.role == "setting"
            and key in own_stems(info)
            and len(all_values(info.var)) >= 3
            and any(str(v).casefold() == "off" for v in all_values(info.var))
        ]
        return f"{m[1]} off" if len(named) == 1 else m[0]

    return _SAID.sub(stopped, instruction)
