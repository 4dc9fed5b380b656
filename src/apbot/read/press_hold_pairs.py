"""One key that steps both ways: a press to the next value, a hold to the previous one.

Panels with three or four keys have no ▲ / ▼: the legend gives one key both directions by the
way it is touched ("MODE … in the list: next size (press) / previous size (hold 2 s)"), or the
steps say it ("Press MODE to go to the next larger size. Hold MODE for 2 seconds to go to the
next smaller size."). The press and the hold of that key are then a stepping pair, as ▲ / ▼
would be, and whatever opens the list hands them its setting.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder

_UP = r"(?:next(?:\s+(?:larger|higher|bigger))?|larger|higher|bigger)"
_DOWN = r"(?:previous|next\s+(?:smaller|lower)|smaller|lower)"
_HELD = r"\((?:long\s+press|(?:press\s+and\s+)?hold)[^)]{0,20}\)"
_PRESSED = r"\((?:short\s+|brief\s+)?press[^)]{0,10}\)"
# a legend's two ways in one breath: "next size (press) / previous size (hold 2 s)"
_LEGEND = re.compile(
    rf"\b{_UP}\s+(?P<noun>[a-z][a-z-]{{1,20}})\s*{_PRESSED}\s*[/,;]\s*(?:or\s+)?"
    rf"{_DOWN}\s+(?P=noun)\s*{_HELD}",
    re.IGNORECASE,
)


def _steps(label: str) -> tuple[re.Pattern[str], re.Pattern[str]]:
    """The steps that say it, key by key: "Press MODE to go to the next larger size", "Hold MODE
    for 2 seconds to go to the next smaller size"."""
    key = re.escape(label)
    go = r"(?:to\s+)?(?:go|step|move|jump)\s+(?:back\s+)?to\s+the\s+"
    return (
        re.compile(
            rf"\bpress\s+{key}\s+(?:once\s+)?{go}{_UP}\s+(?P<noun>[a-z][a-z-]{{1,20}})", re.I
        ),
        re.compile(
            rf"\bhold\s+{key}\b[^.;]{{0,30}}?\s{go}{_DOWN}\s+(?P<noun>[a-z][a-z-]{{1,20}})", re.I
        ),
    )


def press_hold_pairs(b: Builder, keys: list[ActionInfo]) -> dict[str, dict[str, list[str]]]:
    """A key whose press steps up and whose hold steps down the same noun: noun → {"up": [the
    press], "down": [the hold]}; only where both ways of one key are among ``keys``."""
    pairs: dict[str, dict[str, list[str]]] = {}
    for press in keys:
        if press.skill != "press" or len(press.controls) != 1 or press.digit is not None:
            continue
        holds = [k for k in keys if k.skill == "hold" and k.controls == press.controls]
        token = press.controls[0]
        if len(holds) != 1 or token not in b.labels or not b.labels[token].text:
            continue
        noun = _said(b, token)
        if noun and noun not in pairs:
            pairs[noun] = {"up": [press.name], "down": [holds[0].name]}
    return pairs


def _said(b: Builder, token: str) -> str:
    """The noun the key's legend or steps step both ways; "" for none."""
    units = b.manual.units
    up_re, down_re = _steps(b.labels[token].text)
    ups: set[str] = set()
    downs: set[str] = set()
    for i in b.labels[token].mentions:
        text = units[i].text
        m = _LEGEND.search(text)
        if m:
            return m.group("noun").lower()
        ups |= {m.group("noun").lower() for m in up_re.finditer(text)}
        downs |= {m.group("noun").lower() for m in down_re.finditer(text)}
    both = ups & downs
    return sorted(both)[0] if len(both) == 1 else ""
