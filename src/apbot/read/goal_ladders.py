"""Which of a setting's values form a scale, and in what order: numbered levels (1-5, OFF 1 2
3), worded levels (LO / MED / HI), ladders that open with OFF (off, eco, normal, turbo), sizes
("100 W" < "450 W") — what "the lowest", "full power" or "as strong as it goes" pick an end
of (split from ``goal_scales``, which reads the words)."""

from __future__ import annotations

from typing import Any

from apbot.model.schema import DiscreteVariable, NumericVariable, TimeVariable
from apbot.read.goal_values import (
    OFF_WORDS,
    bare_number,
    magnitude,
    numeric_values,
    parse_quantity,
    quantity_dimensions,
)
from apbot.read.goal_view import VarInfo
from apbot.read.goal_vocab import LETTER_WORDS, SCALES, concept, stem


def numbered_levels(info: VarInfo) -> bool:
    """A strength counted in levels: a unitless setting of plain numbers (1-5), or of OFF and
    numbers (OFF, 1, 2, 3), that no word of heat or time names — what "the gentlest level" or
    "as strong as it goes" picks an end of when no setting is named."""
    if info.dimension is not None or isinstance(info.var, TimeVariable):
        return False
    if isinstance(info.var, NumericVariable) and info.var.unit:
        return False
    if {concept("temperature"), concept("time")} & set(info.vocab):
        return False
    if _COUNTED & {stem(w) for w in info.name.replace("_", " ").split()}:
        return False  # "cups 1-12", "rinse 1-3": a number of things, not how strong
    numbers = [v for v in info.values if bare_number(v) is not None]
    rest = [v for v in info.values if bare_number(v) is None]
    return len(numbers) >= 2 and all(str(v).casefold() in (*OFF_WORDS, "none") for v in rest)


# things a setting counts ("cups", "rinses", "slices"): more of them is not a stronger level


# things a setting counts ("cups", "rinses", "slices"): more of them is not a stronger level
_COUNTED = frozenset(
    stem(w)
    for w in (
        "cup", "cups", "rinse", "rinses", "slice", "slices", "serving", "servings", "portion",
        "portions", "egg", "eggs", "loaf", "loaves", "piece", "pieces", "person", "people",
        "persons", "time", "times", "repeat", "repeats", "batch", "batches", "bottle",
        "bottles", "load", "loads", "glass", "glasses", "mug", "mugs", "bowl", "bowls",
        "scoop", "scoops", "spoon", "spoons", "count", "number", "quantity", "amount",
    )
)  # fmt: skip


def worded_levels(info: VarInfo) -> bool:
    """A strength in words (LOW, MEDIUM, HIGH) that no word of heat or time names: as much a
    level as a numbered one, so "as strong as it goes" beside it names neither alone."""
    if info.dimension is not None or not isinstance(info.var, DiscreteVariable):
        return False
    if {concept("temperature"), concept("time")} & set(info.vocab):
        return False
    if _HEAT & {stem(w) for w in info.name.replace("_", " ").split()}:
        return False  # "warmth", "heating": a heat, not a strength
    return len(scaled(info.values)) >= 2


_HEAT = frozenset(stem(w) for w in ("heat", "heating", "heater", "warmth", "warm", "hot", "temp"))


def levels(values: list[Any]) -> list[Any]:
    """The levels of a setting in order, without the OFF a numbered list opens with (OFF, 1,
    2, 3 has three levels: "medium" is 2); other lists as they are."""
    rest = [v for v in values if bare_number(v) is None]
    offs = all(str(v).casefold() in (*OFF_WORDS, "none") for v in rest)
    if rest and len(rest) < len(values) - 1 and offs:
        return ordered_values([v for v in values if bare_number(v) is not None])
    return values


def is_off_level(info: VarInfo, lowest: Any) -> bool:
    """A power or level setting whose lowest value, 0, is off rather than a level."""
    return (
        isinstance(info.var, NumericVariable)
        and info.dimension in (None, "power")
        and bool({concept("power"), concept("level")} & set(info.vocab))
        and magnitude(lowest) == 0
    )


def ordered(info: VarInfo) -> bool:
    return isinstance(info.var, NumericVariable | TimeVariable) or (
        isinstance(info.var, DiscreteVariable)
        and (
            numeric_values(info.values)
            or bool(quantity_dimensions(info.values))
            or len(scaled(info.values)) >= 2
            or (len(ladder(info.values)) >= 2 and not choice_list(info))
            or (len(capped(info.values)) >= 2 and not choice_list(info))
        )
    )


_CHOICE_WORDS = frozenset(
    concept(w) for w in ("program", "programme", "menu", "mode", "function", "food", "course")
) | frozenset(concept(w) for w in ("cycle", "recipe", "cup", "drink", "dish", "type"))


def choice_list(info: VarInfo) -> bool:
    """A setting that names a choice of things (a programme, a menu, a food), not an amount:
    its list may open with OFF/NONE, but "the strongest programme" is no end of it."""
    words = info.name.replace("_", " ").split() + (info.var.label or "").split()
    return any(concept(w.casefold()) in _CHOICE_WORDS for w in words)


def ladder(values: list[Any]) -> list[Any]:
    """Named levels that start with OFF ("off", "eco", "normal", "turbo"): a scale of strength
    listed from nothing up, so the last is the most (empty when the values are not that)."""
    if len(values) < 2 or str(values[0]).casefold() not in (*OFF_WORDS, "none"):
        return []
    if any(parse_quantity(str(v)) is not None for v in values) or scaled(values):
        return []
    return list(values)


_TOPS = frozenset({"max", "maximum", "turbo", "boost"})


def capped(values: list[Any]) -> list[Any]:
    """Named levels listed up to a top (ECO, STD, MAX; QUIET, NORMAL, TURBO): a panel steps
    through its levels from the least and writes the most as MAX, so the list is the scale's
    order (empty when the last value is no such top, or a value is a quantity)."""
    if len(values) < 2 or str(values[-1]).casefold() not in _TOPS:
        return []
    if any(parse_quantity(str(v)) is not None for v in values) or scaled(values):
        return []
    if str(values[0]).casefold() in (*OFF_WORDS, "none"):
        return []  # OFF … TURBO is a ladder, read by :func:`ladder`
    return list(values)


def scaled(values: list[Any]) -> list[Any]:
    """Values that are words of one scale ("low", "medium", "high", or as a display shortens
    them: "LO", "MED", "HI"), in the scale's order."""
    for scale in SCALES:
        found = [v for v in values if _scale_word(v) in scale]
        if len(found) >= 2:
            return sorted(found, key=lambda v: scale.index(_scale_word(v)))
    return []


def _scale_word(value: Any) -> str:
    """The scale's word a value stands for: "lo" is low, "med" medium (else the value)."""
    word = str(value).casefold()
    return LETTER_WORDS.get(word, (word,))[0] if len(word) > 1 else word


def ordered_values(values: list[Any]) -> list[Any]:
    """Values in order of size: numbers and times as they are; of a discrete list, the ones
    that are quantities ("100 W" < "450 W"), by size, or the words of a scale (low < high)."""
    if all(isinstance(v, int | float) for v in values) or all(
        str(v).count(":") == 2 for v in values
    ):
        return values
    sized = [(q[0], v) for v in values if (q := parse_quantity(str(v))) is not None]
    if len(sized) < 2 and scaled(values):
        return scaled(values)
    if len(sized) < 2 and ladder(values):
        return ladder(values)
    if len(sized) < 2 and capped(values):
        return capped(values)
    return [v for _size, v in sorted(sized, key=lambda pair: pair[0])]
