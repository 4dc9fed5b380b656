"""Keys that choose what the one stepping pair changes, told by the steps that use them.

Panels with one ▲ / ▼ (or + / −) pair and several function keys explain each setting as two
steps: "1. Press RUN TIME. The display shows RUN and the run time. 2. Press ▲ or ▼ to change
it", or in one sentence, "touch STERI, then − or +". Read key by key, such a key looks like a
setting of its own (a list printed nearby, a toggle, even START/STOP for START TIME) and the
pair like one amount; the user's setting then has no way to be set. A key pressed in a step
whose next step (or the rest of its own sentence) presses the pair is an entry key of the
pair, unless the key's own sentence gives it a list it cycles by itself ("Press MODE to choose
AUTO, DRY or STORE, then + / −": MODE keeps its list; the pair then sets another amount) or
its step presses it over and over ("Press MENU repeatedly to choose a programme", its list in
a table of its own).
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_common import label_of, mentions_of

# "Press MENU repeatedly to choose a programme": the key walks a list of its own in its step
_CYCLES_RE = re.compile(r"\s*(?:repeatedly|several times|until)\b", re.IGNORECASE)
_STEP_RE = re.compile(
    r"^\W*(?:\d+[.)]\s*)?(?:press|touch|push|use)\w*\s+(?:the\s+)?", re.IGNORECASE
)


def _signs(b: Builder, pair: list[str]) -> list[str]:
    """The printed signs of the pair's keys (▲, ▼, +, −), longest first."""
    found = {b.labels[t].text for t in pair if t in b.labels and b.labels[t].text}
    return sorted(found, key=len, reverse=True)


def pair_follows(b: Builder, key: ActionInfo, pair: list[str]) -> int | None:
    """The unit of the step that presses the pair right after the key is pressed ("1. Press
    START TIME." … "2. Press ▲ or ▼ …", one unit or two on; "touch STERI, then − or +" in one
    sentence), or None when no step of the manual does so."""
    signs = _signs(b, pair)
    if not signs or key.controls[0] not in b.labels:
        return None
    sign = "|".join(rf"(?<!\w){re.escape(s)}(?!\w)" for s in signs)
    label = re.escape(label_of(b, key.controls[0]))
    pressed = re.compile(  # "Press RUN TIME", "Touch FRONT or REAR"
        rf"\b(?:press|touch|push)\w*\s+(?:the\s+)?(?:[^.;]{{0,25}}?(?:\bor|\band|,)\s+)?"
        rf"{label}(?!\w)",
        re.IGNORECASE,
    )
    then = re.compile(rf"^[^.;]{{0,12}}\bthen\s+(?:press\s+|touch\s+|use\s+)?(?:{sign})")
    step = re.compile(rf"{_STEP_RE.pattern}(?:{sign})", re.IGNORECASE)
    units = b.manual.units
    for i in mentions_of(b, key.controls[0]):
        m = pressed.search(units[i].text)
        if m is None or _CYCLES_RE.match(units[i].text, m.end()):
            continue
        if then.search(units[i].text[m.end() :]):
            return i
        for j in (i + 1, i + 2, i + 3):
            if j == i + 3 and any(u.bullet for u in units[i + 1 : i + 3]):
                break  # (a third unit on only when the two between go on the key's own step,
                # "1. Press ADDR. The display shows the address, e.g. ADDR 1.")
            if j < len(units) and step.search(units[j].text):
                return j
            if j < len(units) and pressed.search(units[j].text):
                break  # the next step presses the key again: not a step of the pair
    return None


def lists_own(b: Builder, key: ActionInfo, values_at: int | None) -> bool:
    """The key's list stands in a sentence of its own that names it (MODE's "AUTO → DRY →
    STORE"), not in a table or sentence the pair's step brings ("Press ▲ to go forward … through
    the list:")."""
    if values_at is None:
        return False
    return values_at in set(mentions_of(b, key.controls[0]))


# the pair has no setting of its own: "▲ and ▼ only work after ALERT or ZONE …", "On their own
# they do nothing", "do nothing by themselves"
_SERVES_ONLY_RE = re.compile(
    r"\bonly\s+work\w*\s+(?:after|once|when)\b"
    r"|\bon\s+(?:their|its)\s+own,?\s+(?:they|it)\s+(?:do|does)\s+nothing\b"
    r"|\b(?:do|does)\s+nothing\s+(?:on\s+(?:their|its)\s+own|by\s+(?:themselves|itself))\b",
    re.IGNORECASE,
)


def pair_serves_only(b: Builder, pair: list[str]) -> bool:
    """The manual says the pair works only after another key, doing nothing on its own: it
    sets no quantity of its own, whatever its sentences' ranges are named for."""
    units = b.manual.units
    said = {i for t in pair for i in mentions_of(b, t)}
    return any(_SERVES_ONLY_RE.search(units[i].text) for i in said)
