"""What holding a start key switches, when the manual says so.

Holding START is guessed to stop the programme when the manual is silent, but many panels give
the long press a job of its own: "To switch AUTO OFF on: press and hold START/STOP for 3
seconds", "Hold START 2 s to turn KEEP WARM on or off". A sentence that holds the key and
switches a setting named in capitals on or off makes that setting a toggle of the hold.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.evidence_whose import lead_cell
from apbot.read.roles_holdcell import (
    NOUN_ON_OFF,
    ON_OR_OFF,
    hold_cells,
    lock_or_appliance,
    names_a_setting,
)
from apbot.read.shapes import GROUP_NOUNS, SETTING_NOUNS
from apbot.read.shown import LOCK_CUE
from apbot.read.values import UNIT

# a setting printed in capitals, switched on or off ("switch AUTO OFF on", "turns KEEP WARM off")
_SWITCHED = re.compile(
    r"\b(?:[Ss]witch|[Tt]urn)(?:es|s|ed|ing)?\s+(?:the\s+)?"
    r"(?P<name>[A-Z][A-Z0-9-]+(?: [A-Z][A-Z0-9-]+){0,2})\s+(?:on|off)\b"
)

# where one clause ends and the next begins: a sentence's end, a semicolon, or "then" — "hold
# START to cancel heating, then turn the POWER off" switches POWER by hand, not by the hold
_CLAUSE_RE = re.compile(r"(?<=[.!?;])\s+|,?\s+then\b")


def held_label(b: Builder, info: ActionInfo) -> str | None:
    """The printed name of the key a hold action holds; None for a press or a key the manual
    does not name (nothing to look for in its sentences)."""
    if info.skill != "hold" or not info.controls or info.controls[0] not in b.labels:
        return None
    return b.labels[info.controls[0]].text or None


def held_named_switch(b: Builder, info: ActionInfo) -> tuple[str, int] | None:
    """The setting holding this key switches on or off, and the unit that says so; None when
    no clause both holds the key and switches a setting named in capitals. (Not
    ``roles_common.held_switch``, which reads a lower-case noun near the key's own legend.)"""
    label = held_label(b, info)
    if label is None:
        return None
    held = re.compile(
        rf"\bhold(?:\s+down)?\s+(?:the\s+)?{re.escape(label)}(?!\w)|"
        rf"(?<!\w){re.escape(label)}\s*\(?\s*(?:(?:press|touch|push)\s+and\s+)?hold",
        re.IGNORECASE,
    )
    for i, unit in enumerate(b.manual.units):
        for clause in _CLAUSE_RE.split(unit.text):
            if not held.search(clause):
                continue
            m = _SWITCHED.search(clause)
            if m and m.group("name").upper() != label.upper():
                return m.group("name"), i
    return None


# holding: "Hold for 2 seconds:", "touch and hold ⏻", "long press"
_HOLDING = re.compile(
    r"\b(?:(?:press|touch|push)\s+and\s+)?(?:hold(?:ing)?|held|long[ -]press)\b", re.IGNORECASE
)
# switching the appliance itself (or nothing named) both ways: "switch the cushion on or off",
# "switch the cooler off or on again", "switches on/off"
_BOTH_WAYS = re.compile(
    r"\b(?:switch|turn)(?:es|s|ed|ing)?\s+(?:(?:the|your|this)\s+(?P<noun>[a-z][a-z -]{1,30}?)\s+)?"
    r"(?:on\s*(?:/|or|and)\s*off|off\s*(?:/|or|and)\s*on)\b"
    # what it switches may follow: "switch on or off the child lock"
    r"(?:\s+(?:the|your|this)\s+(?P<after>[a-z][a-z -]{1,30}?)(?=[.,;:!)]|\s*$))?"
    r"|:\s*(?:power\s+)?on\s*/\s*off\b",  # "Hold 2 s: ON/OFF", "Long press: power on/off"
    re.IGNORECASE,
)
# one way only, the other said in a sentence of its own: "Press and hold ⏻ for 2 seconds to
# switch on." … "Press and hold ⏻ for 2 seconds to switch off."
_ONE_WAY = re.compile(
    r"\bto\s+(?:switch|turn)\s+(?:(?:the|your|this|it)\s+(?P<noun>[a-z][a-z -]{0,30}?)\s*)?"
    r"(?P<way>on|off)\b(?!\s*(?:/|or|and)\s*o)",
    re.IGNORECASE,
)
_APPLIANCE_WORDS = {"appliance", "unit", "machine", "device", "product"}
# parts and settings a title may name beside the product ("… with LED display"): switching
# one of them on or off is no power, however often the text says "the display" (a fan, a
# lamp, a clock can be the appliance itself: not here)
_PART_WORDS = {
    *SETTING_NOUNS, *GROUP_NOUNS, "display", "screen", "led", "sound", "beep", "buzzer",
    "signal", "lock", "tank", "water", "lid", "door", "plug", "cable", "cord", "key", "keys",
    "button", "panel", "memory", "remote", "control", "wifi", "app",
}  # fmt: skip
_TITLE_LINES = 15  # the title block: brand, model, what the product is


def _appliance_words(b: Builder) -> set[str]:
    """Words the manual calls the appliance by: the generic ones, and the word of its title
    block ("Dual-zone wine cooler", "Massage Seat Cushion") that the text most often says
    with "the" ("the cooler", "the cushion"); a setting named in a contents list (Sound
    setting) is said less often than the appliance."""
    title = " ".join(b.manual.lines[:_TITLE_LINES]).lower()
    keys = {w for lab in b.labels.values() for w in re.findall(r"[a-z]+", lab.text.lower())}
    candidates = set(re.findall(r"[a-z]{3,}", title)) - keys - _APPLIANCE_WORDS - _PART_WORDS
    said: dict[str, int] = {}
    for unit in b.manual.units:
        for word in re.findall(r"\bthe\s+([a-z]{3,})\b", unit.text.lower()):
            if word in candidates:
                said[word] = said.get(word, 0) + 1
    best = max(said, key=lambda w: said[w], default="")
    return _APPLIANCE_WORDS | ({best} if best else set())


# starting and stopping both: "start or stop smoking", "starts / stops the cycle"
_START_STOP = re.compile(
    r"\b(?:start|stop)(?:s|ing)?\s*(?:or|and|/)\s*(?:start|stop)(?:s|ing)?\b", re.IGNORECASE
)


# the key held before, called "it" in the next clause: "Hold ⏻ for 2 s to switch on; hold it
# again to switch off"
_HOLD_IT = re.compile(r"\bhold(?:\s+down)?\s+it\b", re.IGNORECASE)


def _held_clauses(b: Builder, info: ActionInfo) -> list[tuple[int, str]]:
    """The clauses that hold this one key, with their unit: in the key's own legend row a
    clause led by holding ("SELECT dial | Turn: …. Press: …. Press and hold 2 seconds: start or
    stop smoking."), elsewhere a clause that holds the key by name ("Hold M for 2 seconds")."""
    if info.skill != "hold" or len(info.controls) != 1 or info.controls[0] not in b.labels:
        return []
    label = b.labels[info.controls[0]].text
    if not label:
        return []
    this = re.compile(
        rf"\bhold(?:\s+down)?\s+(?:the\s+)?(?:\w+\s+key\s+\(\s*)?{re.escape(label)}(?!\w)",
        re.IGNORECASE,
    )
    whole = re.compile(rf"(?<!\w){re.escape(label)}(?!\w)")
    units = b.manual.units
    others = [lab.text for t, lab in b.labels.items() if t != info.controls[0] and lab.text]
    out = []
    for i in b.labels[info.controls[0]].mentions:
        unit = units[i]
        # the label as a whole word: a "P" key does not lead "Press P, then hold HEAT …"
        # a numbered row counts too ("1 | ⏻ | -- | 3 s: switch on / off")
        own_row = bool(unit.cells) and bool(whole.search(lead_cell(unit.cells)))
        own_line = not unit.cells and bool(whole.match(unit.text))  # "SELECT dial    Turn: …"
        said = [(i, unit.text)]
        if own_line:  # the legend's next lines, up to the next key's ("Press and hold 2 s: …")
            for k in range(i + 1, min(i + 3, len(units))):
                if units[k].cells or units[k].line > unit.line + 2:
                    break
                if any(units[k].text.startswith(o) for o in others) or not _HOLDING.match(
                    units[k].text
                ):
                    continue
                said.append((k, units[k].text))
        held = set(hold_cells(unit)) if own_row else set()  # under "Press and hold"
        for at, text in said:
            last = False  # the clause before held this key: "hold it again" holds it too
            for clause in re.split(r"(?<=[.!?;])\s+|\s+\|\s+", text):
                holding = bool(_HOLDING.search(clause)) or clause.strip() in held
                again = last and bool(_HOLD_IT.search(clause))
                last = ((own_row or own_line) and holding) or bool(this.search(clause)) or again
                if last:
                    out.append((at, clause))
    return out


def held_start(b: Builder, info: ActionInfo) -> int | None:
    """The unit saying that holding this key starts and stops the appliance's run ("Press
    and hold 2 seconds: start or stop smoking."), for a key not named START; else None."""
    return next((i for i, clause in _held_clauses(b, info) if _START_STOP.search(clause)), None)


def held_power(b: Builder, info: ActionInfo) -> int | None:
    """The unit saying that holding this key switches the appliance itself on and off
    ("①  M   Hold for 2 seconds: switch the cushion on or off.", "⏻ … Touch and hold 3 s:
    switch the cooler off or on again."): in the key's own legend row, or a sentence that
    holds the key. None when no such clause, or when what it switches is a setting (the
    sound, the light: not a word of the title)."""
    if (
        info.controls
        and info.controls[0] in b.labels
        and LOCK_CUE.search(b.labels[info.controls[0]].text)
    ):
        return None  # LOCK held 3 s "on/off": the key lock, not the appliance
    named = _appliance_words(b)
    label = (
        b.labels[info.controls[0]].text if info.controls and info.controls[0] in b.labels else ""
    )
    # a HEAT or SOUND key held "on/off" switches its own setting: only a clause naming the
    # appliance ("switch the cushion on or off") makes such a key the power
    own_setting = bool(set(re.findall(r"[a-z]+", label.lower())) & _PART_WORDS)
    for i, clause in _held_clauses(b, info):
        m = _BOTH_WAYS.search(clause)
        if m is None:
            continue
        nouns = [(m.group(g) or "").lower() for g in ("noun", "after")]  # "… the child lock"
        if own_setting and not any(nouns):
            continue
        if all(not n or n.split()[-1] in named for n in nouns):
            return i
    return _held_each_way(b, info, named, own_setting)


def _held_each_way(b: Builder, info: ActionInfo, named: set[str], own_setting: bool) -> int | None:
    """The first of two clauses holding this key, one "to switch on", the other "to switch
    off" (the appliance, or nothing named): manuals often give switching on and switching off a
    sentence each, and a key held both ways is the power however the two are worded."""
    ways: dict[str, int] = {}
    for i, clause in _held_clauses(b, info):
        m = _ONE_WAY.search(clause)
        if m is None:
            continue
        noun = (m.group("noun") or "").lower().strip()
        if noun and noun.split()[-1] != "it" and noun.split()[-1] not in named:
            continue
        if own_setting and not noun:
            continue
        ways.setdefault(m.group("way").lower(), i)
    return min(ways.values()) if len(ways) == 2 else None


# what a hold's clause says after its colon: "Hold 3 s while OFF: °C / °F"
_HELD_JOB = re.compile(r"\bhold\w*\b[^:|]{0,40}:\s*(?P<job>[^|]+?)\W*$", re.IGNORECASE)
# ... a setting switched ("open-window detection on / off") or values flipped ("°C / °F"); the
# whole job, its "mode" kept in the noun (a key table's hold cell, roles_holdcell's _CELL, drops
# it, and may lead with seconds and end with a sign in brackets)
_SWITCHED_NOUN = re.compile(rf"^{NOUN_ON_OFF}{ON_OR_OFF}$", re.I)
_FLIPPED = re.compile(r"^[^\s/]{1,12}(?:\s*/\s*[^\s/]{1,12})+$")
_WHILE_OFF = re.compile(
    r"\b(?:while|when)\s+(?:it\s+is\s+|switched\s+)?(?:off|in\s+standby)\b", re.I
)
_NOT_A_JOB = {"standby", "on", "off", "all"}


def held_other_job(b: Builder, info: ActionInfo) -> tuple[int, str, list[str], bool] | None:
    """The unit where the power key's own legend gives its hold a job of its own ("⏻  touch:
    on / off  hold 3 s: open-window detection on / off", "Touch: on / off. Hold 3 seconds
    while OFF: °C / °F"): a setting it switches or values it flips between, not switching
    off: (unit, the setting's noun or "", the values it flips between or [], whether only while
    the appliance is off: "while OFF"). None when the
    hold only switches the appliance (or the legend says nothing)."""
    for i, clause in _held_clauses(b, info):
        m = _HELD_JOB.search(clause)
        if m is None or _with_another_key(b, info, clause[: m.start("job")]):
            continue  # "Hold ⏻ and ▲ together for 3 seconds: sound on / off" is a two-key hold
        job = m.group("job").strip()
        switched = _SWITCHED_NOUN.match(job)
        said = re.findall(r"[a-z]+", switched.group("noun").lower()) if switched else []
        if (  # not the lock ("childlock"), the appliance, nor a verb ("switch on / off")
            switched
            and not set(said) & (_NOT_A_JOB | _appliance_words(b))
            and not lock_or_appliance(switched.group("noun"))
            and names_a_setting(switched.group("noun"))
        ):
            return (
                i,
                switched.group("noun").strip(" -").lower(),
                [],
                bool(_WHILE_OFF.search(clause)),
            )
        flipped = [v.strip() for v in job.split("/")] if _FLIPPED.match(job) else []
        if flipped and all(re.fullmatch(UNIT, v, re.IGNORECASE) for v in flipped):
            # units only ("°C / °F"): "I / O", "1 / 2 / 3" or "reset / clear" name no setting
            return i, "", flipped, bool(_WHILE_OFF.search(clause))
    return None


def _with_another_key(b: Builder, info: ActionInfo, held: str) -> bool:
    """The words before a hold's colon hold another key with this one ("hold ⏻ and ▲
    together", "hold both keys"): the job is the pair's, not this key's own."""
    if re.search(r"\b(?:together|both)\b", held, re.IGNORECASE):
        return True
    return any(
        re.search(rf"(?<!\w){re.escape(label.text)}(?!\w)", held)
        for control, label in b.labels.items()
        if control not in info.controls and label.text
    )


def add_held_setting(b: Builder, hold: ActionInfo, at: int, noun: str, values: list[str]) -> None:
    """The setting the power key's hold has in its legend (:func:`held_other_job`): a toggle
    named by the noun, or the units it flips between ("°C / °F")."""
    if noun:
        var = b.add_toggle("_".join(re.findall(r"[a-z0-9]+", noun)), noun.upper(), at)
        b.feature(var, [{"actions": [hold.name], "variable": var, "effect": "toggle"}])
        return
    var = b.add_discrete("unit", values, "", None)
    b.note(f"variables.{var}.values", ", ".join(b.variables[var]["values"]), at)
    b.feature(f"set_{var}", [{"actions": [hold.name], "variable": var, "effect": "next"}])


# a push said to start and stop: "push (click) to start or stop", "press it to start or stop"
_PUSH_STARTS = re.compile(
    r"\b(?:push|press|click)\w*\b(?:[^.;:]{0,24}?\bto|\s*:)\s+(?:start|stop)\w*\s*(?:or|and|/)\s*"
    r"(?:start|stop)\w*\b",  # ("Push: start / stop carbonating", a knob's legend)
    re.IGNORECASE,
)


def _other_key_between(b: Builder, info: ActionInfo, between: str) -> bool:
    """Whether another key is named between this key's word and the clause: a legend's clause
    belongs to the key named nearest before it ("(C) TIMER button: auto-stop time (E) Thumb
    wheel: …; push (click) to start or stop" is the wheel's push, not TIMER's)."""
    return any(
        re.search(rf"(?<!\w){re.escape(label.text)}(?!\w)", between, re.IGNORECASE)
        for token, label in b.labels.items()
        if token not in info.controls and label.text.strip()
    )


def pushed_start(b: Builder, info: ActionInfo) -> int | None:
    """The legend line of a key not named START that says a push of it starts and stops the
    run ("(E) Thumb wheel: turn to choose a programme; push (click) to start or stop"): the
    line names the key's word before the clause; else None."""
    if info.skill != "press" or len(info.controls) != 1:
        return None
    word = info.token.split("_")[0]
    if len(word) < 3:
        return None
    named = re.compile(rf"\b{re.escape(word)}\b", re.IGNORECASE)
    units = b.manual.units
    for i, unit in enumerate(units):
        if unit.cells:
            continue
        # the legend line's start, cut off as a sentence of its own ("FIZZ  knob. Turn: …")
        first = i
        while first and units[first - 1].line == unit.line and not units[first - 1].cells:
            first -= 1
        before = units[first].text if first < i else ""
        for clause in re.split(r"(?<=[.;])\s+", unit.text):
            push = _PUSH_STARTS.search(clause)
            at = unit.text.find(clause) + push.start() if push else -1
            leads = [m for m in named.finditer(unit.text) if m.start() < at]
            if leads and not _other_key_between(b, info, unit.text[leads[-1].end() : at]):
                return i
            if push and push.start() == 0 and named.match(before.lstrip(" *|•-")):
                return i
    return None
