"""Keys named after the modes of one list ("Operating modes: NORMAL, COVER, BOOST" with a COVER
and a BOOST key): each key puts the appliance in its own mode and, pressed again, back in the
mode no key is named after (NORMAL). Read key by key each was an on/off switch of its own
("COVER ... pool-cover mode on / off", "BOOST ... starts a boost"), so the goal's "cover mode"
had no variable, and two such switches on at once is a state the appliance never has. The list
must be led by a group noun (mode, programme …) and name two keys or more and exactly one mode
without a key: a list whose every item is a key is a pad of go-to keys (``roles_pads``)."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.shapes import GROUP_PLURALS

# what a list of modes is led by: a group noun ("Modes", "OPERATING MODES", "Programme") or
# another plural ("Workouts | JUST ROW, TIME, DIST"), not the panel's parts ("Keys: …")
_NOUN = rf"(?:{GROUP_PLURALS}|(?!(?:keys|buttons|pads|controls|lamps|indicators|symbols|signs"
_NOUN += r"|parts|accessories|contents|items|features|options|settings)\b)[A-Za-z]{3,}s)"
# "7  OPERATING MODES: NORMAL, COVER, BOOST", "The unit has three modes: normal, eco and
# holiday" (the noun ends its phrase: "mode button: ..." is no list of modes)
_LED_LIST = re.compile(
    rf"^[\W\d_]*(?:[A-Za-z-]+\s+){{0,5}}?(?P<noun>{_NOUN})\s*:\s*(?P<items>.+)$",
    re.IGNORECASE,
)
_LEAD_CELL = re.compile(rf"^(?:[A-Za-z-]+\s+)?(?P<noun>{_NOUN})$", re.IGNORECASE)
_SPLIT = re.compile(r"\s*(?:,|/|·|\band\b|\bor\b)\s*", re.IGNORECASE)
_LEADER = re.compile(r"\s*(?:\.{3,}|…)\s*\d*\s*$")  # a contents line's dots and page number


def _items(text: str) -> list[str]:
    """The names of a list ("NORMAL, COVER, BOOST"); [] when an item is no short name."""
    text = _LEADER.sub("", text).strip(" .;")
    items = [i.strip(" .;") for i in _SPLIT.split(text)]
    items = [i for i in items if i]
    if len(items) < 3 or any(len(i.split()) > 2 or not re.match(r"^[A-Za-z]", i) for i in items):
        return []
    return items


# the key's own words say a second press leaves its mode: "pressed again, ends it", "on / off"
_AGAIN = re.compile(
    r"\bagain\b|\bon\s*/\s*off\b|\bon or off\b|\bon and off\b|\btoggles?\b|\bleaves?\b",
    re.IGNORECASE,
)


def _toggles(b: Builder, key: ActionInfo) -> bool:
    """Whether a sentence naming the key says, within a few words after its name, that a
    second press leaves the key's mode (else the key only goes to its mode)."""
    label = b.labels[key.controls[0]]
    name = re.compile(rf"(?<![A-Za-z0-9]){re.escape(label.text)}(?![A-Za-z0-9])")
    for i in label.mentions:
        text = b.manual.units[i].text
        for m in name.finditer(text):
            if _AGAIN.search(text[m.end() : m.end() + 60]):
                return True
    return False


def _lists(b: Builder) -> list[tuple[str, list[str], int]]:
    """Each list led by a group noun: (the noun, its items, the unit), prose and table rows."""
    found: list[tuple[str, list[str], int]] = []
    for n, unit in enumerate(b.manual.units):
        if unit.cells:
            lead = _LEAD_CELL.match(unit.cells[0].strip(" *"))
            if lead:
                for cell in unit.cells[1:]:
                    found.append((lead.group("noun"), _items(cell), n))
            continue
        m = _LED_LIST.match(unit.text.strip())
        if m:
            found.append((m.group("noun"), _items(m.group("items")), n))
    return [(noun, items, n) for noun, items, n in found if items]


def mode_keys(b: Builder, keys: list[ActionInfo]) -> list[ActionInfo]:
    """Press keys named after all but one mode of a list led by a group noun: one setting of
    the list's modes, each key going to its own mode (and, where its words say a second press
    leaves it, back to the one no key names, where the appliance starts). Returns the keys
    given this role."""
    named: dict[str, ActionInfo] = {}
    for k in keys:
        if k.skill == "press" and k.controls[0] in b.labels:
            named.setdefault(b.labels[k.controls[0]].text.upper(), k)
    for noun, items, at in _lists(b):
        upper = [i.upper() for i in items]
        if len(set(upper)) != len(upper):
            continue
        keyed = [named[i] for i in upper if i in named]
        free = [i for i in items if i.upper() not in named]
        if len(keyed) < 2 or len(free) != 1 or len({k.name for k in keyed}) != len(keyed):
            continue
        noun = noun.lower()
        noun = noun[:-1] if noun.endswith("s") else noun
        var = b.unique("programme" if noun == "program" else noun, b.variables)
        values = [i.lower() for i in items]
        rest = free[0].lower()
        b.variables[var] = {"type": "discrete", "values": values, "initial": rest}
        b.note(
            f"variables.{var}",
            f"keys named after its {noun}s each switch to their own (or back to {rest}): "
            + ", ".join(values),
            at,
        )
        b.note(f"variables.{var}.initial", f"starts at {rest}, the {noun} no key selects", at)
        for key in keyed:
            own = b.labels[key.controls[0]].text.lower()
            effect: dict[str, object] = {"to": own}
            if _toggles(b, key):
                effect = {"when": {var: own}, "then": {"to": rest}, "otherwise": {"to": own}}
            b.feature(key.token, [{"actions": [key.name], "variable": var, "effect": effect}])
        return keyed
    return []
