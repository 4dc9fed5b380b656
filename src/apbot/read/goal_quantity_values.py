"""Programme values that hold a quantity, named by the quantity said in words: "a 6-volt
battery", "six volts" for 6V NORMAL (a number glued to its unit), "ninety minutes of timed
drying" for TIMED 90 (a word and a number of minutes). Read before the quantities are given to
settings, so the time is not taken for a timer as well."""

from __future__ import annotations

import re

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model, VarInfo
from apbot.read.goal_vocab import stem
from apbot.read.number_tokens import read_number
from apbot.read.numbers import find_mentions

_UNIT_NAMES = {
    "v": ("v", "volt", "volts"),
    "a": ("amp", "amps", "ampere", "amperes"),  # not "a": "2 a day"
    "w": ("w", "watt", "watts"),
    "h": ("h", "hour", "hours", "hr", "hrs"),
    "l": ("l", "litre", "litres", "liter", "liters"),
    "kg": ("kg", "kilo", "kilos", "kilogram", "kilograms"),
}
_GLUED = re.compile(r"(\d+(?:\.\d+)?)([a-z]{1,2})")
_REACH = 3


def quantity_values(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set each selector a quantity-holding value of which the words name."""
    for name, info in view.infos.items():
        if info.role != "setting" or not isinstance(info.var, DiscreteVariable):
            continue
        if name in goal:  # "a 12-volt AGM battery": AGM named it; the 12 volts are its own
            said = _glued(info, text, claimed)
            if said is not None:
                claimed.update(range(said[1], said[2]))
            continue
        found = _glued(info, text, claimed) or _minutes(info, text, claimed)
        if found is not None:
            value, start, end = found
            goal[name] = value
            where[name] = start
            claimed.update(range(start, end))


def _glued(info: VarInfo, text: Text, claimed: set[int]) -> tuple[object, int, int] | None:
    """ "6-volt", "six volts", "6 V" for the one value with the word 6V; among several
    (12V NORMAL, 12V AGM) the one whose other words are said too ("a 12-volt AGM battery"),
    else none — but the quantity is still taken, never a timer's 12 hours."""
    holders: dict[tuple[float, str], list[object]] = {}
    for value in info.values:
        for word in str(value).casefold().split():
            glued = _GLUED.fullmatch(word)
            if glued is not None and glued[2] in _UNIT_NAMES:
                holders.setdefault((float(glued[1]), glued[2]), []).append(value)
    if not holders:
        return None
    for i in range(len(text.tokens)):
        number = read_number(text.tokens, i)
        if number is None or any(k in claimed for k in range(number.start, number.end)):
            continue
        j = number.end + (text.word(number.end) == "-")
        for (amount, unit), values in holders.items():
            if amount == number.value and text.word(j) in _UNIT_NAMES[unit]:
                said = values if len(values) == 1 else _others_said(values, text, claimed)
                if len(said) != 1:
                    claimed.update(range(number.start, j + 1))
                    return None
                return said[0], number.start, j + 1
    return None


def _others_said(values: list[object], text: Text, claimed: set[int]) -> list[object]:
    """The values whose words besides the quantity are all said ("AGM" for 12V AGM)."""
    said = {text.stems[k] for k in range(len(text.tokens)) if k not in claimed}
    out = []
    for value in values:
        rest = [w for w in str(value).casefold().split() if _GLUED.fullmatch(w) is None]
        if rest and all(stem(w) in said for w in rest):
            out.append(value)
    return out


def _minutes(info: VarInfo, text: Text, claimed: set[int]) -> tuple[object, int, int] | None:
    """ "ninety minutes of timed drying" for TIMED 90: a duration in minutes beside the
    value's word, among values that differ by their number (TIMED 30 / 60 / 90)."""
    holders: dict[tuple[str, float], object] = {}
    for value in info.values:
        words = str(value).casefold().split()
        numbers = [w for w in words if re.fullmatch(r"\d+", w)]
        others = [w for w in words if w.isalpha()]
        if len(numbers) == 1 and len(others) == 1 and len(words) == 2:
            holders[(stem(others[0]), float(numbers[0]))] = value
    if len({word for word, _n in holders}) != 1 or len(holders) < 2:
        return None
    for mention in find_mentions(text.tokens, skip=claimed):
        if mention.kind != "duration":
            continue
        near = range(max(0, mention.start - _REACH), min(len(text.tokens), mention.end + _REACH))
        said = {text.stems[k] for k in near if k not in claimed}
        for (word, minutes), value in holders.items():
            if word in said and abs(mention.value / 60 - minutes) < 1e-6:
                return value, mention.start, mention.end
    return None
