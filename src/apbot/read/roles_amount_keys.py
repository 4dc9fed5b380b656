"""Keys printed with an amount ("10s 30s 60s 99s", "1H 2H 4H", "70° 80° 100°"): one setting the
keys set directly, each to its own amount.

A row of keys each labelled with an amount in one unit is a shortcut to values of one setting
(a curing time, a timer, a water temperature). Read key by key, each looked like a switch of
its own (the manual says "sets the curing time to 10 seconds", no on/off), so the setting the
user names ("cure for 30 seconds") had no variable. Two or more such keys left without a role,
all in the same unit, make one numeric setting whose values are the printed amounts; its name
is the noun the keys' sentences set ("Sets the curing time to …"), else the quantity of the
unit (seconds: a time).
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import UNIT_QUANTITY, label_of, mentions_of
from apbot.read.values import gap_pieces, unit_name

# an amount and its unit, the whole label: "10s", "99 s", "2H", "70°C", "500 ml"
_AMOUNT_RE = re.compile(r"(\d+(?:[.,]\d+)?)\s*(s|sec|min|h|hr|°C|°F|°|ml|l|g|%|W)", re.IGNORECASE)
_SETS_RE = re.compile(r"\bsets?\s+the\s+((?:[a-z]+\s+){0,2}?[a-z]+)\s+to\b", re.IGNORECASE)


def _amount(b: Builder, key: ActionInfo) -> tuple[float, str] | None:
    """The amount and canonical unit a key's label prints, the whole label."""
    m = _AMOUNT_RE.fullmatch(label_of(b, key.controls[0]).strip())
    if m is None:
        return None
    amount = float(m.group(1).replace(",", "."))
    return (int(amount) if amount.is_integer() else amount), unit_name(m.group(2))


def _whole(x: float) -> float:
    return int(x) if float(x).is_integer() else x


def _noun(b: Builder, keys: list[ActionInfo], unit: str) -> tuple[str, int | None]:
    """What the keys set, as their sentences name it, and where; else the unit's quantity."""
    for key in keys:
        for i in mentions_of(b, key.controls[0]):
            m = _SETS_RE.search(b.manual.units[i].text)
            if m and not set(words(m.group(1))) & {"display", "appliance", "unit"}:
                return "_".join(words(m.group(1))), i
    return UNIT_QUANTITY.get(unit, "amount"), None


_START_RE = re.compile(r"\b(?:starts?|begins?)\b", re.IGNORECASE)


def _starts(b: Builder, keys: list[ActionInfo]) -> bool:
    """Every key's own sentence says it also starts the appliance."""
    return all(
        any(_START_RE.search(b.manual.units[i].text) for i in mentions_of(b, k.controls[0]))
        for k in keys
    )


def amount_keys(b: Builder, keys: list[ActionInfo]) -> list[ActionInfo]:
    """Make one setting of the press keys in ``keys`` printed with amounts in one unit (two at
    least); returns the keys used."""
    found = [(k, a) for k in keys if k.skill == "press" and (a := _amount(b, k)) is not None]
    units = {a[1] for _, a in found}
    if len(found) < 2 or len(units) != 1:
        return []
    unit = units.pop()
    found.sort(key=lambda f: f[1][0])
    amounts = [a[0] for _, a in found]
    if len(set(amounts)) != len(amounts):
        return []
    used = [k for k, _ in found]
    noun, at = _noun(b, used, unit)
    var = b.unique(noun, b.variables)
    pieces = gap_pieces(amounts, unit)
    b.variables[var] = {
        "label": noun.replace("_", " ").upper(),
        "type": "numeric",
        "unit": unit,
        "ranges": [[_whole(p.low), _whole(p.high), _whole(p.step or 1)] for p in pieces],
    }
    if _starts(b, used) and not any(v.get("label") == "RUN" for v in b.variables.values()):
        # "Sets the curing time to 10 seconds and starts curing at once": each key also starts
        run = b.unique("running", b.variables)
        b.variables[run] = {"type": "discrete", "values": ["off", "on"], "label": "RUN"}
        b.variables[run]["visible"] = False  # (no sign of running read: the loop need not see it)
        b.note(f"variables.{run}", "each amount key starts the appliance", at)
        for k, a in found:
            b.feature(
                f"{var}_{k.token}",
                [
                    {
                        "actions": [k.name],
                        "variable": run,
                        "effect": {"to": "on"},
                        "set": {var: a[0]},
                    }
                ],
            )
    else:
        b.feature(
            f"set_{var}",
            [
                {
                    "actions": [k.name for k in used],
                    "variable": var,
                    "effect": {k.name: {"to": a[0]} for k, a in found},
                }
            ],
        )
    shown = ", ".join(f"{a:g}" for a in amounts)
    b.note(f"variables.{var}", f"keys printed with amounts set it directly: {shown} {unit}", at)
    return used
