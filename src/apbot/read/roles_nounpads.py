"""Keys whose legend rows each select one kind of the same thing ("| ROOM | selects water at
room temperature |", "| COLD | selects chilled water |", "| HOT | selects hot water |"): the
rows share the noun of what they select, and each key names one choice of it, so the keys are
one setting named by that noun (water: room, cold, hot), though no word such as "programme" or
"mode" says so (``roles_pads.SELECTS_ONE`` reads those). Not a noun for an amount or a part of
the appliance: "selects the drying time", "selects the rear zone" pick what the other keys then
adjust, not a choice of their own; nor "selects the next station", a step through a list.
The shared noun is one some object ends in (its head, "sparkling water"), so a shared adjective
("selects hot coffee", "selects hot milk", "selects hot water") names no setting; a row whose
object runs on past it ("still water straight") still holds it."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.goal_twins import PART_NOUNS
from apbot.read.labels import words
from apbot.read.roles_lists import LIST_WORDS
from apbot.read.shapes import SETTING_NOUNS

# "selects chilled water", "starts the rear wash": the verb, then what it selects
_SELECTS = re.compile(
    r"^\s*(?:selects?|chooses?|(starts?))\s+(?:the\s+)?([A-Za-z].*)$", re.IGNORECASE
)
# where the object ends: a clause, an aside, a condition ("– only when unlocked", "at room …")
_OBJECT_END = re.compile(
    r"\s*(?:[;:,–—·(]|\s-\s|\b(?:at|for|with|when|while|if|only|on|in|and|or|to|from|by|until|after|before)\b).*$",
    re.IGNORECASE,
)


def _object_words(cell: str) -> tuple[list[str], bool]:
    """The words of what a key table's cell says the key selects ("hot water"), and whether
    the key starts it ("starts the rear wash")."""
    m = _SELECTS.match(cell)
    if not m:
        return [], False
    obj = _OBJECT_END.sub("", re.sub(r"\([^)]*\)", " ", m.group(2)))
    return words(obj), bool(m.group(1))


def noun_pads(b: Builder, keys: list[ActionInfo]) -> tuple[str, list[ActionInfo], str]:
    """The shared noun and the keys, when two or more press keys' rows of one key table say
        each selects a kind of the same thing (an object of a few words ending in that noun); and
    "off" when each starts one: before any is pressed none of them runs."""
    named = {
        b.labels[k.controls[0]].text.upper(): k
        for k in keys
        if k.skill == "press" and b.labels[k.controls[0]].line is not None
    }
    rows: list[tuple[ActionInfo, list[str], bool]] = []
    header: tuple[str, ...] | None = None
    for unit in b.manual.units:
        if len(unit.cells) < 2 or not unit.header:
            continue
        lead = [c.strip(" *").upper() for c in unit.cells]
        key = next((named[c] for c in lead if c in named), None)
        obj, starts = next(
            (_object_words(c) for c in unit.cells if _object_words(c)[0]), ([], False)
        )
        if key is None or not obj or len(obj) > 3:
            continue
        if header is not None and unit.header != header:
            continue  # one table's rows only
        header = unit.header
        rows.append((key, obj, starts))
    own = {w for k, _, _ in rows for w in words(b.labels[k.controls[0]].text)}
    heads = {obj[-1] for _, obj, _ in rows}  # the nouns the objects end in
    groups: dict[str, list[ActionInfo]] = {}
    started: dict[str, bool] = {}
    for key, obj, starts in rows:  # each word of what a row selects that names no key
        if set(obj) & (set(SETTING_NOUNS) | PART_NOUNS):
            continue  # "the drying time", "the rear zone": which to adjust, no choice
        if set(obj) & LIST_WORDS:
            continue  # "the next station", "the previous track": a step through a list
        for w in obj:
            if w in own or len(w) < 3 or w not in heads:
                continue
            if key not in groups.get(w, []):
                groups.setdefault(w, []).append(key)
                started[w] = started.get(w, True) and starts
    # the noun most rows share ("still water", "sparkling water", "iced water")
    noun, group = max(groups.items(), key=lambda g: len(g[1]), default=("", []))
    if len(group) < 2:
        return "", [], ""
    return noun, group, "off" if started[noun] else ""
