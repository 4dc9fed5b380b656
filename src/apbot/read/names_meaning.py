"""The name of the setting a held key opens, from the words saying what the hold does.

Manuals give one key a second job for holding it, and say the job with a verb: a key
table's column for holding ("| HARDNESS | set the hardness | 3 s: change hardness unit |"),
or the key's legend ("TIME  Touch briefly: the cooking time. Touch and hold for 2 seconds:
opens the delayed start"), or a sentence ("Hold MODE for 3 s to select the eco level"). The
setting is what the verb acts on ("hardness unit", "delayed start"), and the user asks for it
by those words, never by the gesture ("time_hold"). On/off jobs are read elsewhere
(:mod:`apbot.read.roles_holdcell`); fast stepping ("large steps", "10 steps at once"), the
key lock and switching the appliance are jobs, not settings, and give no name here.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_holdcell import _own_rows, hold_cells

_SECONDS = r"(?:for\s+)?(?:about\s+|approx\.?\s+)?\d+(?:[.,]\d+)?\s*(?:s|sec|secs|seconds?)\b"
# the verbs of opening or changing a setting, and the thing they act on
_VERB = r"(?:opens?|selects?|sets?|changes?|enters?|adjusts?|chooses?|switches|calls?\s+up)"
_THING = r"(?:the\s+|a\s+)?(?P<noun>[a-z°][a-z° /-]{1,40}?)"
_END = r"\s*(?:$|[.;,:(\"'|]|\s-\s|\s+(?:with|by|using|for|in|on|to|from)\b)"
# a cell of the column kept for holding: "3 s: change hardness unit", "change °C / °F"
_CELL = re.compile(rf"^\W*(?:{_SECONDS}\s*:?\s*)?{_VERB}\s+{_THING}{_END}", re.I)
# a legend's or sentence's hold: "Touch and hold for 2 seconds: opens the delayed start"
_HOLD_THEN = re.compile(
    rf"\b(?:(?:touch|press|tap|push)\s+(?:and|&)\s+)?hold(?:\s+(?:it|down))?\s*(?:{_SECONDS})?"
    rf"\s*(?::\s*|\s+to\s+){_VERB}\s+{_THING}{_END}",
    re.I,
)
# a legend's hold said of the key as its subject: "Held for 3 seconds it changes the
# hemisphere", "When held for 2 s, it selects the unit" (a sentence of its own, or a clause)
_HELD_IT = re.compile(
    rf"(?:^|[.;:]\s*|\(\w\)\s*)(?:when\s+|if\s+)?held(?:\s+down)?\s*(?:{_SECONDS})\s*,?\s*"
    rf"(?:it\s+)?{_VERB}\s+{_THING}{_END}",
    re.I,
)
# jobs that are not settings: moving faster, locking, switching on, confirming, cancelling
_NOT_A_SETTING = {
    "step", "steps", "large", "faster", "fast", "value", "values", "lock", "key", "keys",
    "appliance", "power", "unit's", "on", "off", "now", "cancel", "it", "them", "this", "that",
    "digits", "digit", "hours", "minutes", "hour", "minute", "display",
}  # fmt: skip
# what a hold opens that is a part of the appliance, not a setting ("hold 3 s to open the door")
_PARTS = {
    "door", "lid", "drawer", "hatch", "cover", "flap", "valve", "basket", "tray", "tank", "latch",
}  # fmt: skip
_CLOCKS = {"clock", "time", "timer"}
_UNIT = re.compile(r"^\s*°\s*[cf]\s*/\s*°\s*[cf]\s*$", re.I)


def _rows(b: Builder, key: ActionInfo) -> list[int]:
    """The key's own legend rows, also when the row is numbered in the key's cell ("(1)
    HARDNESS | set the hardness | 3 s: change hardness unit")."""
    rows = _own_rows(b, key)
    label = b.labels[key.controls[0]].text.upper()
    for i in b.labels[key.controls[0]].mentions:
        cells = b.manual.units[i].cells
        lead = re.sub(r"^\W*(?:\(\d{1,2}\)|\d{1,2}[.)])\s*", "", cells[0]) if cells else ""
        if i not in rows and lead.strip(" *").upper() == label:
            rows.append(i)
    return rows


def _meaning(noun: str) -> str:
    """The setting a verb acts on, as a name's words; "" when it names no setting."""
    noun = noun.strip(" -/").lower()
    if _UNIT.match(noun):  # "change °C / °F": the temperature unit
        return "unit"
    said = [w for w in words(noun) if w.isalpha()]
    if (
        not said
        or len(said) > 3
        or set(said) & (_NOT_A_SETTING | _PARTS)
        or "°" in noun
        or "/" in noun
    ):
        return ""
    if said[0].endswith("ly") and len(said[0]) > 4:
        return ""  # "hold to change quickly": how the hold steps, not what it opens
    if len(said) > 1 and said[0].endswith("ed") and len(said[0]) > 5:
        said[0] = said[0][:-2]  # "delayed start": the delay's start (a time, as "delay" says)
    return " ".join(said)


def held_meaning(b: Builder, key: ActionInfo) -> str:
    """What setting holding this key opens or changes, read from its legend's hold column, the
    line about holding it, or a sentence "hold KEY (N s) to <verb> <setting>"; "" also when
    the key's own name says it ("hold CLOCK to set the clock") or another key is printed with
    that name (its own setting, not this one)."""
    meant = _held_meaning(b, key)
    tokens = {i.token for i in b.infos if i.controls != key.controls} | {key.token}
    if key.token in _CLOCKS and set(words(meant)) & _CLOCKS:
        return ""  # "CLOCK  hold 2 s to set the time of day": the key's own name says it
    return "" if meant.replace(" ", "_") in tokens else meant


def _held_meaning(b: Builder, key: ActionInfo) -> str:
    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return ""
    units = b.manual.units
    label = re.escape(b.labels[key.controls[0]].text)
    named = re.compile(rf"\bhold(?:ing)?\s+(?:the\s+)?{label}\b(?:\s+(?:key|button))?", re.I)
    others = {j for t, lab in b.labels.items() if t != key.controls[0] for j in lab.mentions}
    for i in b.labels[key.controls[0]].mentions:  # said of the hold, before any cell's verb
        for k in range(i, min(i + 3, len(units))):  # ("(C) MENU." then its legend's sentences)
            if k > i and (k in others or units[k].heading != units[i].heading):
                break
            m = _HELD_IT.search(units[k].text)
            if m and (meant := _meaning(m.group("noun"))):
                return meant
    texts: list[str] = []
    for i in _rows(b, key):
        unit = units[i]
        if unit.cells:
            texts += [c for c in hold_cells(unit) if c.strip() not in ("", "-", "--")]
        else:
            texts += [unit.text] + [units[k].text for k in (i + 1,) if k < len(units)]
    for text in texts:
        m = _CELL.match(text) or _HOLD_THEN.search(text)
        if m and (meant := _meaning(m.group("noun"))):
            return meant
    for i in b.labels[key.controls[0]].mentions:
        text = units[i].text
        said = named.search(text)
        if said:  # "Hold TIME for 2 s to open the delayed start"
            m = _HOLD_THEN.search("hold" + text[said.end() :])
            if m and m.start() == 0 and (meant := _meaning(m.group("noun"))):
                return meant
    return ""
