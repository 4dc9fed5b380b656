"""What a key's own legend says of it, for sorting setting keys: a row for holding the key (not the
press's on/off), a cycle of named values in its own legend (a selector), a bare number range
(a number setting).

Apart from ``roles`` because these are tests on one key's sentences, which ``roles.assign`` only
consults while it runs the roles in order.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.roles_common import mentions_of
from apbot.read.roles_holdcell import HELD_SECONDS, HOLD_CELL
from apbot.read.roles_lists import numeric_list
from apbot.read.shapes import Evidence
from apbot.read.text import Unit
from apbot.read.values import ON_OFF_RE


def _named_cycle(b: Builder, key: ActionInfo, ev: Evidence) -> bool:
    """Three or more named values the key steps through, read in its own legend ("PLATE
    Chooses which plates heat. Each press moves on by one: BOTH > LOWER only > UPPER only"),
    and an on/off said elsewhere ("the plates switch off when the timer ends"): a selector. A
    list beside another key's row ("| START | … |" then the programmes round the dial) is no
    evidence against the key's own on/off."""
    values = ev.values or []
    if ev.toggle_at is None or ev.values_at is None or key.controls[0] not in b.labels:
        return False
    said = b.labels[key.controls[0]].mentions
    own = ev.values_at in said or (
        ev.values_at - 1 in said and not b.manual.units[ev.values_at].cells
    )
    # "OFF → BUZZ → RADIO": the switching on and off said with it is a step of the cycle
    off_cycle = "off" in values and "on" not in values
    return (
        len(values) >= 3
        and (off_cycle or not {"on", "off"} & set(values))
        and not numeric_list(values)
        and (off_cycle or ev.values_at != ev.toggle_at)
        and own
        and not _own_legend(b, key, ev.toggle_at)
    )


def _own_legend(b: Builder, key: ActionInfo, at: int) -> bool:
    """Unit ``at`` is the key's own legend: it starts with the key's printed name."""
    label = b.labels[key.controls[0]].text.upper() if key.controls[0] in b.labels else ""
    return bool(label) and b.manual.units[at].text.lstrip(" *|-•").upper().startswith(label)


def _hold_row(b: Builder, key: ActionInfo, at: int | None) -> bool:
    """Whether unit ``at`` is the legend row for holding this key ("FAN (hold 3 s)  switches
    the ioniser on or off") on a panel where the key is also held: not the press's on/off."""
    control = key.controls[0]
    if at is None or control not in b.labels or not b.labels[control].text:
        return False
    if not any(i.skill == "hold" and set(key.controls) <= set(i.controls) for i in b.infos):
        return False
    label = re.escape(b.labels[control].text)
    held = re.compile(rf"^\W*{label}\s*\(?\s*(?:(?:press|touch|push)\s+and\s+)?hold", re.I)
    # "Hold MODE for 2 seconds → the zone timer changes between on and off": the hold's line
    holds_key = re.compile(
        rf"^\W*(?:(?:press|touch|push)\s+and\s+)?hold\s+{label}\s+for\s+\d", re.I
    )
    text = b.manual.units[at].text
    return (
        bool(held.match(text) or holds_key.match(text))
        or _hold_cell(b.manual.units[at])
        or _held_clause(text)
    )


# "… Touch and hold 3 seconds: …", "Hold for 2 s to …", "Held 3 seconds: …": where a legend
# turns to the hold
_HOLD_CLAUSE = re.compile(
    r"\b(?:(?:press|touch|push)\s+and\s+)?(?:hold|held)\b(?:\s+(?:it|the\s+key|for))?\s+\d", re.I
)


def _held_clause(text: str) -> bool:
    """A key's legend whose on/off comes only after the clause for holding it ("Touch: DRY <->
    MOIST. Touch and hold 3 seconds: double seal on / off."): the hold's on/off."""
    clause = _HOLD_CLAUSE.search(text)
    return clause is not None and not ON_OFF_RE.search(text[: clause.start()])


def _hold_cell(unit: Unit) -> bool:
    """A key table's row ("| MIST | level 1 → 2 → 3 | 3 s: warm mist on / off |") whose on/off
    is only in the column for holding the key (headed "hold", or a cell led by the seconds)."""
    if not unit.cells:
        return False
    header = list(unit.header) + [""] * len(unit.cells)
    said = [k for k, cell in enumerate(unit.cells) if ON_OFF_RE.search(cell)]
    return bool(said) and all(
        # (a real column head is short: "Press and hold", "Long press"; a first row taken for
        # the head may say "kept as long as it is plugged in")
        (re.search(r"\bhold|\blong\b", header[k], re.I) and len(_timeless(header[k])) <= 4)
        or re.match(rf"\s*{HOLD_CELL}", unit.cells[k], re.I)
        for k in said
    )


def _timeless(head: str) -> list[str]:
    """A column head's words less how long to hold ("Touch and hold (3 s)", "… 3 seconds")."""
    return re.sub(rf"\(?\b{HELD_SECONDS}\)?", " ", head, flags=re.I).split()


def _numbered(b: Builder, key: ActionInfo, ev: Evidence) -> bool:
    """A key whose own sentence gives a bare number range ("Next menu number (1–15)") sets a
    number, whatever names a table elsewhere gives the numbers."""
    own = set(mentions_of(b, key.controls[0]))
    return (
        bool(ev.ranges)
        and ev.range_at in own
        and ev.values_at not in own
        and not ev.ranges[0].unit
        and ev.ranges[0].high - ev.ranges[0].low >= 2
    )
