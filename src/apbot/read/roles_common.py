"""Words and small lookups the role passes share: which names are amounts, a key's setting name,
what a stepping pair sets."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.held_parts import held_part_toggle
from apbot.read.held_power_only import power_key_steps
from apbot.read.labels import words
from apbot.read.legend_compounds import legend_compound
from apbot.read.named_codes import code_key_noun, spelled_out
from apbot.read.names_meaning import held_meaning
from apbot.read.roles_confirm import confirmed_noun
from apbot.read.roles_holdcell import held_toggle, lock_or_appliance
from apbot.read.shapes import GROUP_NOUNS, SETTING_NOUNS, Evidence


def label_of(b: Builder, token: str) -> str:
    """The control's printed name, or its action word in capitals when the manual has none."""
    return b.labels[token].text if token in b.labels else token.upper()


def first_mention(b: Builder, tokens: list[str]) -> int | None:
    """The first unit naming any of the controls (for the reading report)."""
    for t in tokens:
        if t in b.labels and b.labels[t].mentions:
            return b.labels[t].mentions[0]
    return None


NUMERIC_WORDS = {
    "time", "timer", "delay", "clock", "humidity", "temperature", "temp", "level", "watt",
    "speed", "spin", "weight", "volume", "duration", "hour", "min", "minute", "preset", "reserve",
}  # fmt: skip  # settings that are amounts: "switch the timer off" does not make them toggles


TIME_WORDS = {"time", "timer", "clock", "delay", "duration", "preset", "reserve", "ready"}


FUNCTION_WORDS = {
    *SETTING_NOUNS,
    *GROUP_NOUNS,
    "clock",
    "hour",
    "min",
    "minute",
    "sec",
    "texture",
    "timer",
    "keep",
    "warm",
    "light",
    "lock",
    "delay",
    "preset",
    "size",
    "crust",
    "colour",
    "color",
    "loaf",
    "start",
    "stop",
    "cancel",
    "temp",
    "fan",
    "auto",
    "select",
    "set",
    "memory",
    "sound",
    "quick",
    "express",
    "reserve",
    "taste",
    "add",
    "weight",
    "child",
    "display",
    "eco",
    "rinse",
    "spin",
    "dry",
    "wash",
    "turbo",
    "swing",
    "pump",
    "water",
    "soil",
    "option",
    "options",
}  # what a key does, not a programme it names


def used_actions(b: Builder) -> set[str]:
    return {a for steps in b.features.values() for st in steps for a in st["actions"]}


HOLD_USE_RE = re.compile(
    r"([A-Za-z][A-Za-z -]{2,30}?)\s*\((?:(?:touch|press|tap|push)\s*(?:and|&)\s*)?hold\)",
    re.IGNORECASE,
)


HOLD_THEN_RE = re.compile(  # also a bare "hold" opening one of a legend's uses per gesture:
    # "(short press: hair type; hold 3 seconds: auto-off time)", "(tap: timer, long press: delay)"
    r"(?:\b(?:touch|press|tap|push)\s+(?:and|&)\s+hold|(?:(?<=[(;,·])|(?<=[(;,·]\s))"
    r"(?:hold|long\s+press))(?:\s+(?:for\s+)?\d+(?:[.,]\d+)?\s*"
    r"(?:s|sec|secs|seconds?))?\s*:\s*"
    r"(?!(?:switch|turn)(?:es|s)?\s+(?:on|off)\b)"  # "hold 3 s: switch off": the appliance itself
    r"([A-Za-z][A-Za-z -]{2,40})",
    re.IGNORECASE,
)


HOLD_TO_SWITCH_RE = re.compile(  # "Press and hold for 3 seconds to switch the sound on or off"
    r"\W*\b(?:touch|press|tap|push)\s+(?:and|&)\s+hold(?:\s+(?:it\s+)?(?:down\s+)?(?:for\s+)?"
    r"(?:about\s+)?\d+(?:[.,]\d+)?\s*(?:s|sec|secs|seconds?))?\s+to\s+(?:switch|turn)\s+"
    r"(?:the\s+)?([a-z][a-z -]{2,30}?)\s+(?:on|off)\b",
    re.IGNORECASE,
)

# "Held 3 seconds: switches SmartStart on or off." — a legend's hold clause, then what it switches
HELD_CLAUSE_SWITCH_RE = re.compile(
    r"\W*\b(?:held|hold(?:ing)?|(?:press|touch|push)\s+and\s+hold)(?:\s+(?:down\s+)?for)?\s+"
    r"\d+(?:[.,]\d+)?\s*(?:s|sec|secs|seconds?)\s*[:,–-]\s*(?:it\s+)?(?:switches|turns|toggles)\s+"
    r"(?:the\s+)?([A-Za-z][A-Za-z -]{2,30}?)\s+on\s+(?:or|and|/)\s+off\b",
    re.IGNORECASE,
)


def held_switch(b: Builder, key: ActionInfo) -> tuple[str, int] | None:
    """What holding this key switches on and off, and where the manual says so: "COOK TIME
    Sets the time. Press and hold for 3 s to switch the sound on or off." (the legend's next
    sentence, when it opens with the hold, is still about this key); else None."""
    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return None
    units = b.manual.units
    label = re.escape(b.labels[key.controls[0]].text)
    own = set(words(b.labels[key.controls[0]].text))
    holding = re.compile(  # "Holding FAN switches the ioniser (see 5.6)."
        rf"\bholding\s+(?:the\s+)?{label}\s+(?:(?:key|button)\s+)?(?:switches|turns|toggles)\s+"
        r"(?:the\s+)?([a-z][a-z -]{2,30}?)"
        r"(?:\s+on\s+(?:and|or)\s+off\b|(?:\s+(?:on|off)\b)?\s*(?:[.;,(]|$))",
        re.IGNORECASE,
    )
    # "Hold MODE for 2 seconds → the zone timer changes between on and off"
    changes = re.compile(
        rf"^\W*(?:(?:press|touch|push)\s+and\s+)?hold\s+{label}\s+for\s+[^.:→]{{1,20}}(?:→|:)\s*"
        r"(?:the\s+)?([a-z][a-z -]{2,30}?)\s+(?:changes|switches|toggles)\s+"
        r"between\s+on\s+and\s+off\b",
        re.IGNORECASE,
    )
    for i in b.labels[key.controls[0]].mentions:
        after = units[i + 1].text if i + 1 < len(units) else ""
        for at, said in ((i, changes.search(units[i].text)),
                         (i, HOLD_TO_SWITCH_RE.search(units[i].text)),
                         (i + 1, HOLD_TO_SWITCH_RE.match(after)),
                         (i + 1, _later_clause_hold(after)),
                         (i, holding.search(units[i].text)),
                         (i, HELD_CLAUSE_SWITCH_RE.search(units[i].text)),
                         (i + 1, HELD_CLAUSE_SWITCH_RE.match(after))):  # fmt: skip
            if said and said.re is HELD_CLAUSE_SWITCH_RE and own & set(words(said.group(1))):
                continue  # "SENSOR  Hold 2 s: switches the hand sensor on or off": its own
            if said and not lock_or_appliance(said.group(1)):
                return said.group(1).lower(), at
    return None


def _later_clause_hold(text: str) -> re.Match[str] | None:
    """The legend's next sentence, its press first and its hold after a semicolon: "Press
    briefly to confirm; press and hold for 2 seconds to switch the beeper on or off"."""
    clauses = re.split(r";\s*", text)
    if not re.match(r"\W*(?:press|touch|tap|push)\b", clauses[0], re.IGNORECASE):
        return None  # ("MODE  Press briefly …; press and hold …": another key's, review31)
    for clause in clauses[1:]:
        m = HOLD_TO_SWITCH_RE.match(clause)
        if m:
            return m
    return None


def _of_the(noun: str, own: set[str]) -> str:
    """ "timer of the rear zone" (key REAR) -> "rear timer": the head noun with what names the
    key in the phrase after "of"/"for" (its label's words; else the phrase less its own final
    noun, "zone"); a noun without "of"/"for" as it is."""
    parts = re.split(r"\s+(?:of|for)\s+", noun, maxsplit=1)
    if len(parts) < 2:
        return noun
    head, tail = parts
    rest = [w for w in tail.split() if w.lower() not in ("the", "a", "an", "its", "this", "that")]
    named = [w for w in rest if w.lower() in own]
    if named:
        rest = named
    elif len(rest) >= 2:
        rest = rest[:-1]  # "the rear zone": "zone" is the noun, "rear" says which
    return " ".join([*rest, head]) if rest else head


def hold_use(b: Builder, key: ActionInfo) -> str:
    """What holding a key does when its legend gives a use per way of touching it ("| REAR |
    Selects the rear zone (touch) · rear timer (touch and hold) |"): "rear timer"; else ""."""
    if key.skill != "hold" or len(key.controls) != 1 or key.controls[0] not in b.labels:
        return ""
    for i in b.labels[key.controls[0]].mentions:
        text = b.manual.units[i].text
        after = HOLD_THEN_RE.search(text)  # "| Touch and hold 2 s: timer of the rear zone. |"
        if after:
            own = set(words(b.labels[key.controls[0]].text))
            noun = _of_the(after.group(1).strip(), own)
            if noun and len(noun.split()) <= 3 and not lock_or_appliance(noun):
                return noun.lower()
        label = re.escape(b.labels[key.controls[0]].text)
        row = re.match(  # "FAN (hold 3 s)  switches the ioniser on or off": the ioniser
            rf"\W*{label}\s*\((?:(?:press|touch|push)\s+and\s+)?hold[^)]*\)\s*"
            r"(?:switches|turns)\s+(?:the\s+)?([a-z][a-z -]{2,30}?)\s+(?:on\b|off\b)",
            text,
            re.IGNORECASE,
        )
        if label and row and not lock_or_appliance(row.group(1)):
            return row.group(1).lower()
        switched = held_switch(b, key)
        if switched:
            return switched[0]
        m = HOLD_USE_RE.search(text)
        if m:
            noun = re.split(r"[·;,:|]|\)", m.group(1))[-1].strip()
            if noun and len(noun.split()) <= 3 and not lock_or_appliance(noun):
                return noun.lower()
    return ""


def var_name(b: Builder, key: ActionInfo) -> str:
    """The setting's name: the key's printed name when it spells out the action's word
    ("KITCHEN TIMER" for timer, "WATER LEVEL" for water), else the action's word."""
    base = key.token if key.skill == "press" else f"{key.token}_hold"
    held = held_part_toggle(b, key)  # "Touch: DRY / MOIST.  Hold 3 s: double seal on / off"
    held = held or hold_use(b, key) or held_toggle(b, key) or held_meaning(b, key)
    if held:
        return "_".join(words(held))
    stepped = power_key_steps(b, key)
    if stepped:  # "each short press of ⏻ moves one step up the output scale": the output
        return stepped
    confirmed = confirmed_noun(b, key)
    if confirmed:  # "OK  Ends the entry of a stitch number": the stitch
        return confirmed
    lab = b.labels.get(key.controls[0])
    if key.skill == "press" and (lab is None or lab.line is None):
        return _heading_word(b, key.token) or base
    if key.skill != "press" or lab is None or lab.line is None:
        return base
    if len(key.token) == 1:  # a key printed as a letter ("M"): what its sentences say it picks
        nouns = "|".join(GROUP_NOUNS)
        moves = re.compile(rf"\b(?:next|previous|choose|select)\w*\s+(?:the\s+)?({nouns})\b", re.I)
        for i in lab.mentions:
            m = moves.search(b.manual.units[i].text)
            if m:
                return m.group(1).lower()
    glossed = _short_press_noun(b, key, lab.mentions)
    if glossed:  # "MENU — short press: privacy code.": a key of no meaning names its setting
        return glossed
    said = _unit_key_sets(b, key, lab.mentions)
    if said:  # "HOUR key - sets the start time": a key named for its step sets that time
        return said
    coded = code_key_noun(b, lab) or spelled_out(b, lab)
    if coded:  # "F1 ♫ — sound on / off": the sound; "DISC  Opens the discrimination level"
        return coded
    opened = opened_setting(b, lab.mentions)
    own = [w[:3] for w in words(key.token.replace("_", " ")) + words(lab.text) if len(w) >= 3]
    if opened and not any(w[:3] in own for w in words(opened.replace("_", " "))):
        return opened  # "* | opens the entry-delay setting": the key is a way in, the setting
        # a noun (AIR TIME opening "the airing-time setting" keeps its own name)
    compound = legend_compound(b, key.token, lab.text, lab.mentions)
    if compound:  # "☾ Backlight." for ``light``: the legend's whole noun
        return compound
    lw = [w for w in words(lab.text) if w.isalpha()]
    tw = words(key.token.replace("_", " "))
    if 1 < len(lw) <= 3 and all(any(x == t or x.startswith(t) for x in lw) for t in tw):
        return "_".join(lw)
    return base


# keys whose printed name says only that they open something (set16)
_BARE_KEYS = frozenset({"menu", "set", "func", "function", "fn", "option", "options"})
# "MENU — short press: privacy code. Hold 3 s: …": the setting a short press opens
_SHORT_PRESS_RE = re.compile(
    r"\bshort press\s*[:—–-]\s*(?:the\s+)?([a-z]+(?:[ -][a-z]+)?)\s*[.;]", re.I
)


def _short_press_noun(b: Builder, key: ActionInfo, mentions: list[int]) -> str:
    """What the legend says a short press of a key printed only as MENU or SET opens ("short
    press: privacy code"): the setting's name as users say it, not the key's."""
    if key.skill != "press" or key.token not in _BARE_KEYS:
        return ""
    return _first_named(b, mentions, _SHORT_PRESS_RE)


def _first_named(b: Builder, mentions: list[int], pattern: re.Pattern[str]) -> str:
    """The words ``pattern`` captures in the first of a key's sentences it matches, as a
    variable name; "" when none matches."""
    for i in mentions:
        m = pattern.search(b.manual.units[i].text)
        if m:
            return "_".join(words(m.group(1)))
    return ""


_UNIT_KEYS = frozenset({"hour", "hours", "hr", "min", "minute", "minutes"})
_SETS_TIME_RE = re.compile(
    r"\bsets?\s+(?:the\s+)?((?:[a-z]+[\s-]+)?(?:time|delay|timer))\b", re.IGNORECASE
)


# "opens the entry-delay setting", "opens the alarm-time adjustment": the key leads into a
# setting the legend names (the noun is the setting, the key only its way in)
_OPENS_SETTING_RE = re.compile(
    # (the verb and its article: "left open while setting" is a slot left open, no key)
    r"\bopens?\s+(?:the|its)\s+([a-z]+(?:[\s-][a-z]+){0,2}?)\s+(?:setting|adjustment)\b",
    re.I,
)


def opened_setting(b: Builder, mentions: list[int]) -> str:
    """The setting a key's own sentence says it opens, as a variable name; "" when none."""
    for i in mentions:
        m = _OPENS_SETTING_RE.search(b.manual.units[i].text)
        if m and not set(words(m.group(1))) & {"the", "a", "menu", "settings"}:
            return "_".join(words(m.group(1).replace("-", " ")))
    return ""


def _unit_key_sets(b: Builder, key: ActionInfo, mentions: list[int]) -> str:
    """What a key named by a unit of time (HOUR, MIN) sets, when its own sentence says so
    ("HOUR key - sets the start time in TIMER mode"): the setting is that time, the key only
    its step; "" when the key is no such key or no sentence names it."""
    if key.token not in _UNIT_KEYS:
        return ""
    return _first_named(b, mentions, _SETS_TIME_RE)


def turns(actions: list[ActionInfo]) -> tuple[list[str], list[str]]:
    """A dial's clockwise and counter-clockwise turns (the action names), for stepping."""
    return (
        [i.name for i in actions if i.skill == "turn_cw"],
        [i.name for i in actions if i.skill == "turn_ccw"],
    )


def dedupe(items: list[str]) -> list[str]:
    return list(dict.fromkeys(items))


def plain(text: str) -> str:
    return re.sub(r"\s+", " ", text.lower()).strip()


def token_of(b: Builder, action: str) -> str:
    return next(i.token for i in b.infos if i.name == action)


def mentions_of(b: Builder, token: str) -> list[int]:
    return b.labels[token].mentions if token in b.labels else []


def numeric_list(values: list[str]) -> bool:
    """Numbers ("20 30 40 60 90", "1.5 kg"), or times of a dial written h:mm ("0:20 · 0:40")."""
    return all(
        re.fullmatch(r"\d+(?:[.,]\d+)?\s*[a-z%°]*", v.strip().lower()) for v in values
    ) or clock_list(values)


def shown_prefix(values: list[str]) -> str:
    """The letter or two every item of a list prints before its amount ("r0°, r90°, r180°":
    an angle the display writes after an r); "" when the items differ in it or carry no unit
    after the number (P1, P2 … are named programmes, not amounts)."""
    found = [
        re.fullmatch(r"([A-Za-z]{1,2})(\d+(?:[.,]\d+)?)\s*([°%]\w*)", v.strip()) for v in values
    ]
    if len(values) < 2 or not all(found):
        return ""
    prefixes = {m.group(1) for m in found if m}
    return prefixes.pop() if len(prefixes) == 1 else ""


def clock_list(values: list[str]) -> bool:
    """Durations written h:mm, every one ("0:00, 0:20, 0:40, 1:00, 1:30, 2:00")."""
    return len(values) >= 2 and all(re.fullmatch(r"\d{1,2}:[0-5]\d", v.strip()) for v in values)


# the quantity a range in a unit measures (a range in °C is a temperature)
UNIT_QUANTITY = {"°C": "temperature", "°F": "temperature", "%": "humidity", "min": "time",
                 "h": "time", "s": "time", "W": "power"}  # fmt: skip


def stepped_noun(b: Builder, tokens: list[str], ev: Evidence | None = None) -> str:
    """What a pair of stepping keys sets: the quantity its range is in, else the setting noun
    its sentences name most often."""
    unit = ev.ranges[0].unit if ev is not None and ev.ranges else ""
    if unit in UNIT_QUANTITY:
        return UNIT_QUANTITY[unit]
    shown = _shown_new(b, tokens)
    if shown:
        return shown
    counts: dict[str, int] = {}
    # another key's name ("while the TIMER is being set they change the hours") is what the
    # pair sets for that key, not its own setting
    keys = {lab.text.lower() for t, lab in b.labels.items() if t not in tokens and lab.text}
    units = b.manual.units
    own_rows = {i for t in tokens for i in mentions_of(b, t) if units[i].cells and units[i].header}
    for i in b.context(tokens):
        if i not in own_rows and any(units[i].header == units[r].header for r in own_rows):
            continue  # the key table's next row is about the next key
        text = units[i].text.lower()
        for noun in (n for n in SETTING_NOUNS if n not in keys):
            counts[noun] = counts.get(noun, 0) + len(re.findall(rf"\b{noun}\b", text))
    best = max(SETTING_NOUNS, key=lambda n: (counts.get(n, 0), -SETTING_NOUNS.index(n)))
    return best if counts.get(best) else ""


# "Tap ▲ or ▼: the desk moves 1 cm … and the display shows the new height": what a press of
# the pair changes is what the display then shows anew (set16)
_SHOWS_NEW_RE = re.compile(r"\b(?:display|screen)\s+shows\s+the\s+new\s+([a-z]{3,})\b", re.I)
_NOT_QUANTITIES = {"setting", "settings", "value", "values", "number", "figure", "reading"}


def _shown_new(b: Builder, tokens: list[str]) -> str:
    """The one noun the pair's own sentences say the display shows anew after a press ("the
    display shows the new height"); "" when none or several."""
    units = b.manual.units
    found = {
        m.group(1).lower()
        for t in tokens
        for i in mentions_of(b, t)
        for m in _SHOWS_NEW_RE.finditer(units[i].text)
    } - _NOT_QUANTITIES
    return found.pop() if len(found) == 1 else ""


def _heading_word(b: Builder, token: str) -> str | None:
    """A key whose name is printed nowhere (an icon, "☼"): the word of a heading that the
    action's clipped word begins ("6.3 Brightness" for ``bright``), the setting's own name
    as the manual and its users say it; None where no heading or more than one word fits."""
    if "_" in token or len(token) < 4:
        return None
    found = {
        w
        for u in b.manual.units
        if u.heading and u.text == u.heading
        for w in words(u.heading)
        if w.startswith(token) and w != token and w.isalpha() and len(w) <= len(token) + 6
    }
    return found.pop() if len(found) == 1 else None
