"""A setting kept in the unit a selector chooses (TEMPERATURE in °C or °F, HARDNESS in °dH,
ppm or gpg): a number said with one of the selector's units ("110 °F", "100 degrees
Fahrenheit", "18 grains per gallon") is the setting's value in that unit's case, and the
selector goes to that unit — unless it already shows it (the unit the panel starts in is how
the number was said, not a request). A unit written as initials is named by its words ("grains
per gallon" for GPG)."""

from __future__ import annotations

import re
from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import DiscreteVariable, NumericVariable
from apbot.read.goal_fit import fit
from apbot.read.goal_text import Text
from apbot.read.goal_values import phrase_words
from apbot.read.goal_view import Goal, Model
from apbot.read.number_tokens import read_number
from apbot.read.numbers import Mention

_DEGREES = frozenset({"degrees", "degree", "deg", "°"})
UNIT_WORDS = (
    frozenset(
        {
            "celsius",
            "fahrenheit",
            "c",
            "f",
            "dh",
            "fh",
            "ppm",
            "gpg",
            "mmol",
            "kg",
            "lb",
            "lbs",
            "st",
            "hpa",
            "inhg",
        }
    )
    | frozenset({"g", "oz", "ml", "l", "km", "mi", "miles", "kcal", "cal", "kj", "mph", "kmh"})
    | frozenset({"mmhg", "kpa", "psi", "bar"})  # pressure, as a blood-pressure cuff shows it
    | frozenset({"rpm", "rcf", "x g", "xg", "×g", "× g"})  # a rotor's speed, or its g-force
)
"""Units a selector may offer for one quantity (a scale of temperature, of water hardness, of
weight or distance): the values of a unit selector, never of a programme."""


def said_units(view: Model, goal: Goal) -> None:
    """ "as hot as it goes in Celsius" on a panel that shows °C: the unit it starts in, named
    beside a setting kept in it, is how the user counts, not a switch asked for."""
    for name in list(goal):
        if not unit_selector(view, name):
            continue
        chooser = view.infos[name].var
        assert isinstance(chooser, DiscreteVariable)
        kept = any(
            getattr(info.var, "depends_on", None) == name and other in goal
            for other, info in view.infos.items()
        )
        if kept and str(goal[name]) == str(_starting(chooser)):
            del goal[name]


def unit_selector(view: Model, name: str) -> bool:
    """``name`` is a selector of units for one quantity (°C / °F), not a programme."""
    chooser = view.infos.get(name)
    if chooser is None or not isinstance(chooser.var, DiscreteVariable):
        return False
    return all(_unit_names(chooser.var, u) and _a_unit(chooser.var, u) for u in chooser.values)


def unit_cases(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Read "<number> <unit of the selector>" for each setting kept per unit."""
    for name, info in view.infos.items():
        var = info.var
        selector = getattr(var, "depends_on", None)
        if name in goal or not isinstance(var, NumericVariable) or not selector:
            continue
        chooser = view.infos.get(selector)
        if chooser is None or not isinstance(chooser.var, DiscreteVariable):
            continue
        names = {u: _unit_names(chooser.var, u) for u in chooser.values}
        if not all(names.values()) or not all(_a_unit(chooser.var, u) for u in chooser.values):
            continue
        for unit, said in names.items():
            found = _said_with(text, claimed, said)
            if found is None:
                continue
            number, end = found
            trial = {**goal, selector: unit}
            value = fit(view, info, Mention("number", number.value, number.start, end), trial)
            if value is None:
                continue
            goal[name] = value
            where[name] = number.start
            claimed.update(range(number.start, end))
            if unit == _starting(chooser.var):
                if goal.get(selector) == unit and where.get(selector, -1) >= number.end:
                    del goal[selector]  # "22 °dH" on a panel that shows °dH: no switch
            else:
                goal[selector] = unit
                where[selector] = number.start
            break
        if selector not in goal:
            _initials_named(text, claimed, names, goal, where, selector)


def _unit_names(var: DiscreteVariable, unit: Any) -> list[list[str]]:
    """The word sequences a unit is said by: its name, its display text (a scale's letter by
    the scale's name), and for a name of initials (GPG) the words they stand for, matched by
    their first letters."""
    out = []
    for label in (str(unit), (var.show or {}).get(unit) if isinstance(var.show, dict) else None):
        if label:
            words = [w.casefold() for w in phrase_words(str(label).replace("°", " "))]
            if words and all(w.isalpha() for w in words):
                out.append(words)
                if words in (["c"], ["f"]):  # °F is said "degrees Fahrenheit"
                    out.append([_SCALES[words[0]]])
                out += _SAID_AS.get(" ".join(words), [])
    return out


_G_FORCE = [["g"], ["x", "g"], ["times", "g"], ["g", "force"], ["xg"]]
_SAID_AS = {"x g": _G_FORCE, "xg": _G_FORCE, "rcf": _G_FORCE}
_SAID_AS["rpm"] = [["revolutions", "a", "minute"], ["revolutions", "per", "minute"]]
"""How people say a rotor's units: "14,000 times g", "800 g" (beside an rpm / x g selector the
g is the g-force, no gram), "6500 revolutions a minute"."""


_SCALES = {"c": "celsius", "f": "fahrenheit"}


def _a_unit(var: DiscreteVariable, value: Any) -> bool:
    """A value that is a unit (FAHRENHEIT, °dH, PPM), by its name or its display text."""
    show = var.show.get(value) if isinstance(var.show, dict) else None
    return any(
        label is not None
        and (
            str(label).casefold().lstrip("°").strip() in UNIT_WORDS
            or len(_unit_parts(str(label))) > 1  # "fl oz", "lb:oz": units joined
        )
        for label in (value, show)
    )


def _unit_parts(label: str) -> list[str]:
    """The units a compound unit joins ("lb:oz" pounds and ounces, "fl oz" fluid ounces), or
    [] when one part is no unit."""
    parts = [p for p in re.split(r"[\s:./+-]+", label.casefold().lstrip("°")) if p]
    return parts if parts and all(p in UNIT_WORDS or p == "fl" for p in parts) else []


def _starting(var: DiscreteVariable) -> Any:
    try:
        domain = build_domain(var)
    except ValueError:
        return None
    return domain.values[domain.initial]


def _said_with(text: Text, claimed: set[int], names: list[list[str]]) -> tuple[Any, int] | None:
    """A number followed by (degrees and) one of the unit's names: the number and the end."""
    for i in range(len(text.tokens)):
        if i in claimed:
            continue
        number = read_number(text.tokens, i)
        if number is None or any(k in claimed for k in range(number.start, number.end)):
            continue
        if text.word(i) in ("a", "an"):
            continue  # "over a distance": no number
        j = number.end
        while text.word(j) in _DEGREES:
            j += 1
        word = text.word(j).lstrip("°")
        for words in names:
            if _words_at(text, j, words, word):
                return number, j + _length(text, j, words, word)
    return None


def _words_at(text: Text, j: int, words: list[str], first: str) -> bool:
    if [first, *(text.word(j + d) for d in range(1, len(words)))] == words:
        return True
    return _initials_at(text, j, words) > 0


def _length(text: Text, j: int, words: list[str], first: str) -> int:
    initials = _initials_at(text, j, words)
    return initials if initials else len(words)


_NOT_INITIALS = frozenset({"the", "and", "for", "you", "your", "its", "this", "that", "with"})
"""Words no unit's initials stand for ("Switch the" is no ST)."""


def _initials_at(text: Text, j: int, words: list[str]) -> int:
    """ "grains per gallon" for GPG: words from j whose first letters spell a 2–4 letter name
    (each at least three letters long, or a joining word); the number of words, or 0."""
    if len(words) != 1 or not 2 <= len(words[0]) <= 4:
        return 0
    letters = words[0]
    said = [text.word(j + d) for d in range(len(letters))]
    if all(w[:1] == c for w, c in zip(said, letters, strict=True)) and all(
        len(w) >= 3 and w.isalpha() and w not in _NOT_INITIALS for w in said
    ):
        return len(letters)
    return 0


def _initials_named(
    text: Text,
    claimed: set[int],
    names: dict[Any, list[list[str]]],
    goal: Goal,
    where: dict[str, int],
    selector: str,
) -> None:
    """ "switch to grains per gallon": the unit named by its words alone."""
    for j in range(len(text.tokens)):
        if j in claimed:
            continue
        for unit, said in names.items():
            size = max((_initials_at(text, j, words) for words in said), default=0)
            if size:
                goal[selector] = unit
                where[selector] = j
                claimed.update(range(j, j + size))
                return


_MORE_NAMES = {"st": ["stone", "stones"], "lb": ["pound", "pounds", "lbs"]}
_MORE_NAMES |= {"kg": ["kilogram", "kilograms", "kilo", "kilos"], "g": ["gram", "grams"]}
_MORE_NAMES |= {"oz": ["ounce", "ounces"], "ml": ["millilitre", "millilitres", "milliliters"]}
_MORE_NAMES |= {"mi": ["mile", "miles"], "km": ["kilometre", "kilometres", "kilometers"]}
_MORE_NAMES |= {"kpa": ["kilopascal", "kilopascals"], "mmhg": ["mercury"]}  # "millimetres of …"
_MORE_NAMES |= {"bar": ["bars"], "psi": ["pounds per square inch"]}
_MORE_NAMES |= {"inhg": ["inches"], "hpa": ["hectopascals", "hectopascal", "millibars"]}
"""The words a unit symbol a selector offers is said by ("in stones" for ST)."""


def _said_unit_names(var: DiscreteVariable, unit: Any) -> set[str]:
    """One-word names of a selector's unit: its own, its display text's, and the words the
    symbol stands for."""
    names = {words[0] for words in _unit_names(var, unit) if len(words) == 1}
    names |= {"".join(words) for words in _unit_names(var, unit) if len(words) > 1}  # kPa
    for name in list(names):
        names.update(_MORE_NAMES.get(name, ()))
    return names


def named_units(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """ "readings in Fahrenheit", "switch the scale to pounds", "I weigh myself in stones": a
    unit said with no number before it names the value of the one unit selector that offers
    it (a number's unit, "300 ml", is the number's), unless negated ("instead of kg")."""
    selectors = [n for n in view.infos if n not in goal and unit_selector(view, n)]
    said = {n: _selector_names(view, n) for n in selectors}
    for name in selectors:  # two selectors (°C / °F and hPa / inHg): each its own words
        others = {w for n, units in said.items() if n != name for ws in units.values() for w in ws}
        _unit_named(text, goal, claimed, where, name, said[name], others)


def _selector_names(view: Model, name: str) -> dict[Any, set[str]]:
    """The words each unit of selector ``name`` is said by."""
    var = view.infos[name].var
    assert isinstance(var, DiscreteVariable)
    values = view.infos[name].values  # a selector kept per mode lists its units per case
    return {unit: _said_unit_names(var, unit) for unit in values}


def _unit_named(
    text: Text,
    goal: Goal,
    claimed: set[int],
    where: dict[str, int],
    name: str,
    names: dict[Any, set[str]],
    others: set[str],
) -> None:
    """The first unit of selector ``name`` (said by ``names``) said in ``text`` by a word no
    other selector offers (``others``)."""
    values = list(names)
    compounds = {unit: _said_compound(unit) for unit in values}
    for j, token in enumerate(text.tokens):
        word = token.text.lstrip("°")
        if j in claimed or read_number(text.tokens, j - 1) is not None:
            continue
        if text.word(j - 1) in ("°",) and read_number(text.tokens, j - 2) is not None:
            continue
        if text.word(j - 1) == "of" and text.word(j - 2) == "instead":
            continue
        column = _column_unit(text, j, values)
        if column is not None:  # "in inches of mercury": inHg, not the mmHg "mercury" names
            goal[name] = column
            where[name] = j
            claimed.update(range(j, j + 3))
            return
        joined = [unit for unit, said in compounds.items() if _says_all(text, j, said)]
        if len(joined) == 1:  # "in fluid ounces", "pounds and ounces": the joined unit
            goal[name] = joined[0]
            where[name] = j
            claimed.update(range(j, j + 3))
            return
        units = [unit for unit, said in names.items() if word in said]
        if len(units) == 1 and word not in others:
            goal[name] = units[0]
            where[name] = j
            claimed.add(j)
            return


_LENGTHS = {"inch": "in", "inches": "in", "millimetre": "mm", "millimetres": "mm"}
_LENGTHS |= {"millimeter": "mm", "millimeters": "mm", "centimetre": "cm", "centimetres": "cm"}
_LENGTHS |= {"centimeter": "cm", "centimeters": "cm"}
_COLUMNS = {"mercury": "hg", "water": "h2o"}
"""Pressures said as the height of a column ("inches of mercury" for inHg, "centimetres of
water" for cmH2O): a length's symbol joined to the liquid's."""


def _column_unit(text: Text, j: int, values: list[Any]) -> Any | None:
    """The selector's unit a column pressure from ``j`` names, if it offers it."""
    length, liquid = _LENGTHS.get(text.word(j)), _COLUMNS.get(text.word(j + 2))
    if length is None or liquid is None or text.word(j + 1) != "of":
        return None
    symbol = length + liquid
    found = [v for v in values if "".join(ch for ch in str(v).lower() if ch.isalnum()) == symbol]
    return found[0] if len(found) == 1 else None


def _said_compound(unit: Any) -> list[set[str]]:
    """Per part of a joined unit ("fl oz", "lb:oz"), the words it is said by ("fluid",
    "ounces"); [] for a unit of one part."""
    parts = _unit_parts(str(unit))
    if len(parts) < 2:
        return []
    return [{p, *_MORE_NAMES.get(p, ()), *(("fluid",) if p == "fl" else ())} for p in parts]


def _says_all(text: Text, j: int, said: list[set[str]]) -> bool:
    """The words from ``j`` name every part of a joined unit in turn ("and" may join them)."""
    if not said:
        return False
    k = j
    for index, words in enumerate(said):
        if index and text.word(k) in ("and", "&", "+"):
            k += 1
        if text.word(k) not in words:
            return False
        k += 1
    return True
