"""The unit of a list of bare numbers, when the list says it once or its name says its kind.

Manuals print a row of choices with the unit only once ("LENGTH  30 40 50 60 80 100 mm"), or
as lamps named for time whose legend gives the minutes elsewhere ("TIME: 30 60 90 120 180 ∞").
A reader keeps the numbers bare, so "a 50 mm label" or "dry them for two hours" matched no
value and the goal lost the setting. A bare number of such a list takes the quantity in that
unit: the one unit its other values carry, else minutes for a list named for time (the unit a
row of drying, cooking or run times is counted in).
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.goal_values import parse_quantity
from apbot.read.goal_view import VarInfo
from apbot.read.goal_vocab import concept
from apbot.read.numbers import Mention

_TIME_WORDS = frozenset(concept(w) for w in ("time", "timer", "duration", "delay"))

_MINUTE = 60.0

_PRINTED = re.compile(r"[-+]?\d+(?:\.\d+)?")


def _listed_unit(info: VarInfo) -> tuple[str, float] | None:
    """The one (dimension, factor) the list's unit-bearing values share, if they all share one;
    or the unit its display template prints after every value ("{value} s": seconds)."""
    show = getattr(info.var, "show", None)
    if isinstance(show, str) and show.strip().startswith("{value}"):
        q = parse_quantity(show.replace("{value}", "1"))
        if q is not None and q[1] is not None:
            return q[1], q[0]
    found = set()
    for value in info.values:
        q = parse_quantity(str(value))
        printed = _PRINTED.match(str(value).strip())
        if q is not None and q[1] is not None and printed and float(printed[0]):
            found.add((q[1], round(q[0] / float(printed[0]), 9)))  # "6 cm": 60 mm per unit 10
    return found.pop() if len(found) == 1 else None


def bare_value_fits(info: VarInfo, number: float, mention: Mention) -> bool:
    """Whether the bare value ``number`` of ``info``'s list is the quantity the mention says."""
    if info.dimension is not None:
        return False
    listed = _listed_unit(info)
    if mention.kind == "duration":
        if listed is None and _TIME_WORDS & set(info.vocab):
            listed = ("time", _MINUTE)
        said = mention.value  # seconds
    elif mention.kind == "quantity" and mention.dimension is not None and mention.unit:
        said = mention.value  # in the dimension's base unit, as parse_quantity gives values
    else:
        return False
    if listed is None or listed[0] != (mention.dimension or "time"):
        return False
    return abs(number * listed[1] - said) < 1e-6 * max(1.0, abs(said))


def bare_choice(info: VarInfo, domain: list[Any], mention: Mention) -> Any:
    """The one bare value of the domain the mention names in the list's unit, else None."""
    found = []
    for value in domain:
        q = parse_quantity(str(value))
        if q is not None and q[1] is None and bare_value_fits(info, q[0], mention):
            found.append(value)
    return found[0] if len(found) == 1 else None
