"""What holding a key switches, from the part of its legend kept for holding.

Key tables give one key two jobs: a column "Touch and hold" beside "Short touch" ("| MIST |
level 1 → 2 → 3 | 3 s: warm mist on / off |"), or a second line under the key's row ("NEEDLE
Short press: stop up or down" then "Hold for 2 seconds: twin-needle mode on/off"). The on/off
thing named there is what the hold switches: a toggle of its own, named after it.
"""

from __future__ import annotations

import re

from apbot.read.actions import PRESS_VERBS, TURN_VERBS, ActionInfo
from apbot.read.build import Builder
from apbot.read.evidence_whose import lead_cell
from apbot.read.held_task_rows import held_task_row
from apbot.read.text import Unit
from apbot.read.value_lists import find_list
from apbot.read.values import ON_OFF_RE

_SECONDS = r"(?:for\s+)?\d+(?:[.,]\d+)?\s*(?:s|sec|secs|seconds?)\b"
# how long to hold, as a key table writes it: "3 s", "2 sec", "5 seconds"
HELD_SECONDS = r"\d+(?:[.,]\d+)?\s*s(?:ec\w*)?\b"
# a cell of the column kept for holding: it says "hold" or leads with the seconds
HOLD_CELL = rf"(?:hold\b|{HELD_SECONDS})"
# a thing switched: "warm mist on / off", "sound off or on" (the thing as ``noun``)
NOUN_ON_OFF = r"(?P<noun>[a-z][a-z -]{2,30}?)\s+"
ON_OR_OFF = r"(?:on\s*(?:/|or)\s*off|off\s*(?:/|or)\s*on)"
# the verb a hold's job may be said with: "switches the hand sensor on or off"
_SWITCH_VERB = r"(?:(?:switch|turn|toggle)(?:e?s)?\s+(?:the\s+)?)"
_HELD = re.compile(  # "Hold for 2 seconds: twin-needle mode on/off", "3 s: warm mist on / off",
    # "Hold 3 seconds to switch the auto switch-off off or on"
    rf"^\W*(?:(?:(?:press|touch|push)\s+and\s+)?hold\s*(?:{_SECONDS})?|{_SECONDS})"
    rf"(?:\s*:\s*{_SWITCH_VERB}?|\s+to\s+{_SWITCH_VERB}|(?<=s)\s+for\s+)"  # ("2 s for scan on/off")
    rf"{NOUN_ON_OFF}(?:mode\s+)?{ON_OR_OFF}\b",
    re.IGNORECASE,
)
# a cell under a column kept for holding names the thing alone: "end signal on / off"
_CELL = re.compile(
    rf"^\W*(?:{_SECONDS}\s*:\s*)?{NOUN_ON_OFF}(?:mode\s+)?"
    rf"{ON_OR_OFF}\W*(?:\([^()]*\)\W*)?$",  # "(SOFT)": its sign
    re.IGNORECASE,
)
_SENTENCE_RE = re.compile(r"(?<=[.;])\s+")
# a header for holding: "Touch and hold", "Long press", "Keep touching (printed below)"
_HOLD_HEAD = re.compile(r"\bhold|\blong\b|\bkeep\s+(?:touching|pressing|pushing)\b", re.I)


def hold_cells(unit: Unit) -> list[str]:
    """A row's cells under a header for holding ("Touch and hold", "Long press")."""
    return [
        cell for head, cell in zip(unit.header, unit.cells, strict=False) if _HOLD_HEAD.search(head)
    ]


def own_hold_cells(b: Builder, key: ActionInfo) -> list[str]:
    """The cells under a header for holding in the key's own table rows."""
    units = b.manual.units
    return [cell for i in _own_rows(b, key) if units[i].cells for cell in hold_cells(units[i])]


# a legend's callout read as a cell of its own: "(A)", "[1]", "①"
_MARK = re.compile(r"\(\w\)|\[\w\]|[①-⑳❶-❿➀-➉]")


def _own_rows(b: Builder, key: ActionInfo) -> list[int]:
    """The units of the key's own legend: a line or row led by its printed name (a row may be
    numbered first: "2 | HEAT | …")."""
    if len(key.controls) != 1 or key.controls[0] not in b.labels:
        return []
    label = b.labels[key.controls[0]].text.upper()
    if not label:
        return []
    rows = []
    for i in b.labels[key.controls[0]].mentions:
        unit = b.manual.units[i]
        led = lead_cell(unit.cells).strip(" *").upper() if unit.cells else ""
        lettered = len(unit.cells) >= 3 and re.fullmatch(r"[A-Z]", unit.cells[0].strip())
        if lettered:  # "| C | PROG | Next programme | …": the rows counted by letters
            led = unit.cells[1].strip(" *").upper()
        marked = len(unit.cells) == 2 and _MARK.fullmatch(unit.cells[0].strip())
        if marked:  # "(A) | MODE - next screen; …": a legend in columns, led by its callout
            led = unit.cells[1].strip(" *").upper()
        if (
            unit.text.lstrip(" *|-•").upper().startswith(label)
            or led == label
            or (marked and re.match(rf"{re.escape(label)}(?![\w])", led))
        ):
            rows.append(i)
    return rows


# the lock of a door or lid ("door lock released"), not of the keys
_DOOR_LOCK = re.compile(r"\b(?:door|lid|hatch|cover|drawer)\s+(?:is\s+)?lock", re.I)


def held_lock(b: Builder, key: ActionInfo) -> bool:
    """The key's row in a key table says, in its column for holding, that the hold is the
    lock ("| ALARM | door alarm off / on | 5 s: key lock on / off |")."""
    if key.skill != "hold":
        return False
    units = b.manual.units
    return any(
        re.search(r"\block\b", cell, re.I) and not _DOOR_LOCK.search(cell)
        for i in _own_rows(b, key)
        if units[i].cells
        for cell in hold_cells(units[i])
    )


_LOCK_WORDS = frozenset({"lock", "lockout", "safety", "key", "keys"})
_ITSELF = frozenset({"appliance", "power"})
_SOUNDS = frozenset({"tone", "tones", "beep", "beeps", "sound", "sounds", "click", "clicks"})


def lock_or_appliance(noun: str) -> bool:
    """What a hold switches names the key lock ("key lock", "childlock", "child safety": the lock
    by another name) or the appliance itself ("appliance on / off", "main power"), not a setting
    of its own. The appliance only as the head, the noun's last word: "power saving" is a
    setting; and a clock is no lock ("clock display on / off")."""
    said = re.findall(r"[a-z]+", noun.lower())
    if said and said[-1] in _SOUNDS:
        return False  # "key tone", "key beep": the sound the keys make, no lock
    return bool(said) and (
        said[-1] in _ITSELF
        or any(w in _LOCK_WORDS or (w.endswith("lock") and w != "clock") for w in said)
    )


def names_a_setting(noun: str) -> bool:
    """Whether what a hold switches on / off is a setting's name: "switch on / off", "turn on /
    off" lead with the verb and switch the appliance itself."""
    first = re.findall(r"[a-z]+", noun.lower())[:1]
    verbs = {*PRESS_VERBS, *TURN_VERBS}
    return bool(first) and not {first[0], first[0][:-1], first[0][:-2]} & verbs  # "switches"


def held_toggle(b: Builder, key: ActionInfo) -> str:
    """The on/off thing holding this key switches, read from its legend's hold part; ""."""
    if key.skill != "hold":
        return ""
    units = b.manual.units
    for i in _own_rows(b, key):
        unit = units[i]
        candidates = hold_cells(unit) if unit.cells else []
        if not unit.cells:  # the line after the key's name ("STIR  hold 3 s: slow stir on/off"),
            # and the legend's next lines, when they name no key of their own
            candidates.append(_after_label(b, key, unit.text))
            # (and its clauses: "backlight on / off; hold 2 seconds for auto scan on / off")
            candidates += [c for c in _after_label(b, key, unit.text).split(";")[1:] if c.strip()]
            candidates += _next_rows(b, key, i)
        else:  # a sentence of the row led by the hold ("Character style. Hold 2 s: … on / off"),
            # the first one too ("| SENSOR | Hold for 2 seconds: switches the hand sensor … |")
            candidates += [said for cell in unit.cells[1:] for said in _SENTENCE_RE.split(cell)]
        cells = set(hold_cells(unit)) if unit.cells else set()
        for text in candidates:
            m = _HELD.match(text) or (_CELL.match(text) if text in cells else None)
            if m and not lock_or_appliance(m.group("noun")) and names_a_setting(m.group("noun")):
                return m.group("noun").strip(" -").lower()
    noun = held_task_row(b, key, _CELL)  # "| red light on / off | hold MODE 2 s |"
    return noun if noun and not lock_or_appliance(noun) and names_a_setting(noun) else ""


def _next_rows(b: Builder, key: ActionInfo, i: int) -> list[str]:
    """The legend's two lines after the key's, up to one led by another key's printed name
    ("▲ / ▼ - level up / down (hold 2 s: …)" then "⏻ - hold 2 s: remote on / off": ⏻'s row)."""
    units = b.manual.units
    out = []
    for k in (i + 1, i + 2):
        if k >= len(units) or _led_by_other(b, key, k):
            break
        out.append(units[k].text)
    return out


def _led_by_other(b: Builder, key: ActionInfo, k: int) -> bool:
    """Line ``k`` is a legend row of another control: it mentions that control and starts with
    a short name or sign, then a dash or colon ("⏻ - hold 2 s: …", "SEND - sends …")."""
    if not re.match(r"\W*\S{1,12}\s*[-–—:]\s", b.manual.units[k].text):
        return False
    return any(k in lab.mentions for token, lab in b.labels.items() if token not in key.controls)


# the part of a legend kept for a short touch: "touch: daily drying timer on / off"
_TOUCHED = re.compile(
    rf"(?:^|[\s.;])(?:short\s+|brief\s+)?(?:touch|press|tap|push)(?:\s+briefly)?\s*:\s*"
    rf"{NOUN_ON_OFF}(?:mode\s+)?{ON_OR_OFF}\b",
    re.IGNORECASE,
)
_HOLD_PART = re.compile(rf"\bhold\b[^.;:]{{0,20}}:|^\W*{HELD_SECONDS}\s*:", re.IGNORECASE)


def way_switched(b: Builder, key: ActionInfo) -> str:
    """What this way of touching the key switches on and off, when the key's own legend gives a
    use per way ("TIMER  touch: daily drying timer on / off  hold 3 s: set the drying time",
    "STAGE  Press: next stage. Hold 2 seconds: slow speed on / off"): the noun; else "".

    Said so, the on/off is the job of that way of touching even when its noun names an amount
    (a timer, a speed): the amount itself is what the other way sets, or the noun is a mode
    ("slow speed"), not a value to step."""
    if key.skill == "hold":
        return held_toggle(b, key)
    if key.skill != "press":
        return ""
    units = b.manual.units
    for i in _own_rows(b, key):
        held = hold_cells(units[i]) if units[i].cells else []
        if not held and not _HOLD_PART.search(units[i].text):
            continue  # no use kept for holding: the legend gives no way of touching its own
        m = _TOUCHED.search(units[i].text)
        if m and not lock_or_appliance(m.group("noun")) and names_a_setting(m.group("noun")):
            return m.group("noun").strip(" -").lower()
    return ""


def _after_label(b: Builder, key: ActionInfo, text: str) -> str:
    """A legend line less the key's printed name that leads it ("AUGER  hold 3 seconds: …")."""
    label = b.labels[key.controls[0]].text
    return re.sub(rf"^[\s*|•-]*{re.escape(label)}\b", "", text, count=1, flags=re.I)


def held_values(b: Builder, key: ActionInfo, at: int | None) -> list[str]:
    """The values holding this key flips between, when row ``at`` of a key table gives its
    on/off to the short touch and names the values in the column for holding ("| HEAT |
    heating on / off | change °C / °F |"): °C and °F; else []."""
    if key.skill != "hold" or at is None or at not in _own_rows(b, key):
        return []
    unit = b.manual.units[at]
    held = hold_cells(unit) if unit.cells else []
    if not held or any(ON_OFF_RE.search(cell) for cell in held):
        return []
    for cell in held:
        found = find_list(cell)
        if found and len(found[0]) >= 2 and not {"on", "off"} & {v.lower() for v in found[0]}:
            return found[0]
    return []
