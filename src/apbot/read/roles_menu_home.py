"""The stepping pair a settings menu borrows, when it also moves a quantity of its own.

A menu's ▲ / ▼ change the value of the item shown; outside the menu the same pair often sets
one quantity directly (a humidity, a tip temperature). Apart from ``roles_menu`` because it
reads the pair's legend, not the menu's items.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder

# "▲  On the home screen: humidity up. In the menu: the next value.": what the pair moves
# when no menu is open, said beside its use in the menu
_HOME_NOUN_RE = re.compile(
    r"\b(?:on|from|in|at)\s+the\s+(?:home|main|idle|standby|start)\s+(?:screen|display|view)\b"
    r"[^.:;]*[:,]\s*(?:the\s+)?(?P<noun>[a-z][a-z-]+(?:\s+[a-z][a-z-]+)?)\s+(?:up|down)\b",
    re.IGNORECASE,
)
# "▲ / ▼ — temperature up / down (10 °C a press). In the SET menu: the next value."
_OWN_NOUN_RE = re.compile(
    r"^[^A-Za-z]*[—–:-]\s*(?:the\s+)?(?P<noun>[a-z][a-z-]+(?:\s+[a-z][a-z-]+)?)\s+up\s*"
    r"(?:/|and|or)\s*down\b"
)
_STOPS_RE = re.compile(r"\bstops\s+at\b|\bdoes\s+not\s+wrap\b|\bno\s+wrap", re.IGNORECASE)


def home_quantity(b: Builder, up: str, down: str) -> bool:
    """The pair that steps the menu's values also moves a quantity of its own on the home
    screen ("▲ On the home screen: humidity up. In the menu: the next value."): that
    quantity is a setting the pair changes directly, with the values its section lists
    ("OFF ▸ 1 ▸ 2 … ▸ 8") and end stops when the manual says it stops. Whether it was read:
    a menu of letter codes keeps the pair only then."""
    by_name = {k.name: k for k in b.infos}
    tokens = [c for a in (up, down) for c in by_name[a].controls]
    nouns: dict[str, int] = {}
    for t in tokens:
        lab = b.labels.get(t)
        for i in lab.mentions if lab else []:
            text = b.manual.units[i].text
            m = _HOME_NOUN_RE.search(text) or _OWN_NOUN_RE.match(text)
            if m:
                nouns.setdefault(m.group("noun").lower(), i)
    if len(nouns) != 1:
        return False
    noun, at = next(iter(nouns.items()))
    ev = b.evidence(tokens)
    if ev.values and len(ev.values) >= 2:
        var = b.add_discrete(noun, ev.values, noun.upper(), ev)
    else:  # (a range the manual gives the noun elsewhere: "The plate heat runs from 30 °C …")
        var = b.add_number(noun, noun.upper(), ev, cyclic=False)
    if any(_STOPS_RE.search(b.manual.units[i].text) for t in tokens for i in b.labels[t].mentions):
        b.variables[var]["wrap"] = False
    effect = {up: "next", down: "prev"}
    b.feature(f"set_{var}", [{"actions": [up, down], "variable": var, "effect": effect}])
    b.note(f"variables.{var}", "the pair's own quantity on the home screen", at)
    return True
