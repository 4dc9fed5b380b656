"""What a walk's texts say about a setting the belief lacks: its definition, read off the
texts one key showed press after press (the variable finder's inference, by code and without
a session: :func:`infer_setting`), how a goal value is typed on a keypad, and the word a lamp
adds to a display.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from apbot.agent.infer import infer_template, ranges_from_values
from apbot.agent.quantities import summary
from apbot.model.display import display_value
from apbot.model.domain import ValueProblem, normalise, parse_value
from apbot.model.schema import DiscreteVariable, NumericVariable, TimeStyle, TimeVariable
from apbot.model.values import parse_hms, unit_of

TIME_STYLES: tuple[TimeStyle, ...] = ("h:mm", "mm:ss", "hh:mm", "hh:mm:ss", "min", "h")
_NUMBER = re.compile(r"^\s*([-+]?\d+(?:\.\d+)?)\s?(.*?)\s*$")
GAP = re.compile(r"\s{2,}")  # between the main display and each lamp


@dataclass(frozen=True)
class Learnt:
    """A setting read off a walk: its definition (model data), the key's effect, where the walk
    left it."""

    variable: dict[str, Any]
    effect: str
    current: Any
    note: str


def infer_setting(
    name: str, texts: Sequence[str], kind: str, last: str | None = None
) -> Learnt | None:
    """A setting's definition from the texts one key showed, press after press (the last one
    may repeat an earlier one: the walk went round, or stopped at an end); ``last`` is the text
    the display shows now (where the setting is). ``kind`` is tried first ("worded": only a
    word of its own per value).

    >>> learnt = infer_setting("temperature", ["TEMP 180°C", "TEMP 190°C", "TEMP 200°C",
    ...                                        "TEMP 200°C"], "numeric")
    >>> learnt.variable["ranges"], learnt.variable["unit"], learnt.variable["label"]
    ([[180, 200, 10]], '°C', 'TEMP')
    >>> flow = infer_setting("airflow", ["FLOW high", "FLOW low", "FLOW high"], "discrete")
    >>> flow.variable["values"], flow.variable["wrap"], flow.variable["label"]
    (['high', 'low'], True, 'FLOW')
    """
    distinct = list(dict.fromkeys(texts))
    if len(distinct) < 2:
        return None
    wrap = len(texts) > len(distinct) and texts[-1] == distinct[0] and len(distinct) > 1
    readers = {
        "time": _time_setting,
        "numeric": _numeric_setting,
        "discrete": _discrete_setting,
        "worded": _worded_setting,
    }
    order = [kind] if kind == "worded" else [kind, "numeric", "time", "discrete", "worded"]
    found = None
    for candidate in dict.fromkeys(order):
        found = readers[candidate](distinct)
        if found is not None:
            break
    if found is None:
        return None
    variable, values, template = found
    variable["wrap"] = wrap
    label, _, rest = template.partition(" ")
    if "show" in variable:
        pass  # a word of its own for each value
    elif rest == "{value}" and "{" not in label:
        variable["label"] = label
    else:
        variable["show"] = template
    effect = "next"
    numbers = [v for v in values if isinstance(v, int | float)]
    if len(numbers) == len(values) and numbers != sorted(numbers) and not wrap:
        effect = "prev"
    variable["initial"] = values[0]
    note = f"values {summary([str(v) for v in values])}" + (", wraps" if wrap else "")
    shown_last = last if last in distinct else texts[-1]
    return Learnt(variable, effect, values[distinct.index(shown_last)], note)


def _split(distinct: Sequence[str], words: bool) -> tuple[str, list[str], str] | None:
    """The common text around the varying part of each text."""
    template = infer_template(distinct, lambda v: v, lambda t: t or None, words=words)
    if template is None:
        return None
    prefix, _, suffix = template.partition("{value}")
    middles = [t[len(prefix) : len(t) - len(suffix)] for t in distinct]
    return prefix, middles, suffix


def _numeric_setting(distinct: Sequence[str]) -> tuple[dict[str, Any], list[Any], str] | None:
    split = _split(distinct, words=False)
    if split is None:
        return None
    prefix, middles, suffix = split
    numbers: list[float] = []
    units = set()
    for middle in middles:
        match = _NUMBER.match(middle)
        if match is None:
            return None
        numbers.append(float(match.group(1)))
        units.add(match.group(2))
    if len(units) != 1:
        return None
    unit = units.pop()
    if suffix and not unit and unit_of(suffix.strip()) is not None:
        unit, suffix = suffix.strip(), ""  # "8 min", "180°C": the unit stayed outside the value
    values = [int(n) if n.is_integer() else n for n in numbers]
    variable: dict[str, Any] = {
        "type": "numeric",
        "ranges": [list(r) for r in ranges_from_values(values)],
        "unit": unit,
    }
    spec = NumericVariable.model_validate(variable)
    if any(
        prefix + display_value(spec, v) + suffix != t for v, t in zip(values, distinct, strict=True)
    ):
        return None
    return variable, values, prefix + "{value}" + suffix


def _time_setting(distinct: Sequence[str]) -> tuple[dict[str, Any], list[Any], str] | None:
    split = _split(distinct, words=False)
    if split is None:
        return None
    prefix, middles, suffix = split
    for style in TIME_STYLES:
        probe = TimeVariable(type="time", ranges=[("00:00:00", "99:00:00", 1)], format=style)
        try:
            values = [parse_value(probe, m) for m in middles]
        except ValueProblem:
            continue
        if any(display_value(probe, v) != m for v, m in zip(values, middles, strict=True)):
            continue
        seconds = [parse_hms(v) for v in values]
        ranges = [
            [
                f"{a // 3600:02d}:{a % 3600 // 60:02d}:{a % 60:02d}",
                f"{b // 3600:02d}:{b % 3600 // 60:02d}:{b % 60:02d}",
                int(s),
            ]
            for a, b, s in ((int(x), int(y), int(z)) for x, y, z in ranges_from_values(seconds))
        ]
        variable = {"type": "time", "ranges": ranges, "format": style}
        return variable, values, prefix + "{value}" + suffix
    return None


def _discrete_setting(distinct: Sequence[str]) -> tuple[dict[str, Any], list[Any], str] | None:
    split = _split(distinct, words=True)
    if split is None:
        return None
    prefix, middles, suffix = split
    values = [m.strip() for m in middles]
    if any(not v for v in values) or len(set(values)) != len(values):
        return None
    return {"type": "discrete", "values": values}, values, prefix + "{value}" + suffix


def _worded_setting(distinct: Sequence[str]) -> tuple[dict[str, Any], list[Any], str] | None:
    """Texts with nothing in common (``CUP 150mL``, ``MUG 300mL``, ``FREE``): a value each,
    named by its first word, shown as the whole text.

    >>> _worded_setting(["MUG 300mL", "FREE"])[0]
    {'type': 'discrete', 'values': ['mug', 'free'], 'show': {'mug': 'MUG 300mL', 'free': 'FREE'}}
    """
    values = [text.split()[0].casefold() if text.split() else "" for text in distinct]
    if any(not v.isalpha() for v in values) or len(set(values)) != len(values):
        return None
    show = dict(zip(values, distinct, strict=True))
    return {"type": "discrete", "values": values, "show": show}, list(values), "{value}"


def _fits(variable: dict[str, Any], goal_value: Any) -> bool:
    """Whether ``goal_value`` reads as a value of the setting a walk found: in its unit for a
    number or time (the range may be longer than the walk went), among its words if a word."""
    spec: DiscreteVariable | NumericVariable | TimeVariable
    try:
        kind = variable["type"]
        body = {k: v for k, v in variable.items() if k not in ("initial", "wrap")}
        if kind == "discrete":
            spec = DiscreteVariable.model_validate(body)
            normalise(spec, goal_value)  # one of its words, however written
        else:
            spec = (NumericVariable if kind == "numeric" else TimeVariable).model_validate(body)
            parse_value(spec, goal_value)
    except (ValueProblem, ValueError):
        return False
    return True


_CLOCK_RE = re.compile(r"(?<![\d:])([01]?\d|2[0-3]):([0-5]\d)(?![\d:])")
_LASTING_RE = re.compile(
    r"^\s*\d+(?:\.\d+)?\s*(?:h|hr|hrs|hours?|min|mins|minutes?|s|sec|seconds?)\s*$"
)


def day_walk(texts: list[str], goal_value: Any) -> bool:
    """A walk whose clock times go round midnight (… 23:30, 00:00 …) shows a time of day: a
    duration the goal asks for ("2 h", "15 min") is not one of its values."""
    if not _LASTING_RE.match(str(goal_value)):
        return False
    hours = [int(m.group(1)) if (m := _CLOCK_RE.search(t)) else None for t in texts]
    return any(a == 23 and b == 0 for a, b in itertools.pairwise(hours))


def _kind_of(goal_value: Any) -> str:
    """What kind of setting a goal value is most likely for: a clock-like time, a number (with
    a unit or not: "20 min" may be either, which the display decides), or a word."""
    text = str(goal_value).strip()
    if re.fullmatch(r"\d+:\d{2}(:\d{2})?", text):
        return "time"
    if isinstance(goal_value, int | float) and not isinstance(goal_value, bool):
        return "numeric"
    return "numeric" if re.match(r"^\s*[-+]?\d", text) else "discrete"


def lamp_word(lit: str, unlit: str) -> str | None:
    """The one word a display shows more when a lamp is lit (``SYNC``), if that is all that
    tells the two texts apart: a word with letters or a symbol, and no digits (not a value).

    >>> lamp_word("SYNC  Z1 air fry", "1: 200°C  Z1 air fry"), lamp_word("LIGHT", "")
    ('SYNC', 'LIGHT')
    >>> lamp_word("☾  RUN", "RUN"), lamp_word("--  RUN", "RUN")
    ('☾', None)
    >>> lamp_word("160°C", "") is None
    True
    """
    shown = [part for part in GAP.split(lit.strip()) if part]
    others = set(GAP.split(unlit.strip()))
    new = [part for part in shown if part not in others]
    if len(new) != 1 or any(c.isdigit() for c in new[0]):
        return None
    if not any(c.isalpha() or not c.isascii() for c in new[0]):
        return None  # punctuation alone ("--"); letters or a symbol lamp (☾, ⚡) it may be
    return new[0]


def _typing(goal_value: Any) -> tuple[str, str, Any, str] | None:
    """How to type a goal value on a keypad: (kind, digits, the value as the setting holds it,
    entry format) — a whole number as itself, a time as minutes and seconds (``1:30`` →
    ``130``), or hours and minutes past 99 minutes.

    >>> _typing(70), _typing("1 min 30 s")
    (('numeric', '70', 70, 'number'), ('time', '130', '00:01:30', 'mm:ss'))
    >>> _typing("2 h"), _typing("1000 ml")
    (('time', '200', '02:00:00', 'h:mm'), ('numeric', '1000', 1000, 'number'))
    """
    probe = TimeVariable(type="time", ranges=[("00:00:00", "99:59:59", 1)])
    try:  # a clock, or a number with a unit of time
        clock = _kind_of(goal_value) == "time" or any(c.isalpha() for c in str(goal_value))
        value = parse_value(probe, goal_value) if clock else None
    except ValueProblem:
        value = None
    if value is None:
        number = _whole(goal_value)
        return None if number is None else ("numeric", str(number), number, "number")
    seconds = parse_hms(value)
    if seconds < 100 * 60:
        return "time", str(seconds // 60 * 100 + seconds % 60), value, "mm:ss"
    if seconds % 60 == 0:
        return "time", str(seconds // 3600 * 100 + seconds % 3600 // 60), value, "h:mm"
    return None


def _whole(value: Any) -> int | None:
    """A goal value as a whole number (``70``, ``"70 %"``), if it is one."""
    match = _NUMBER.match(str(value))
    if match is None:
        return None
    number = float(match.group(1))
    return int(number) if number.is_integer() and number >= 0 else None


def typed_setting(
    name: str, texts: list[str], typing: tuple[str, str, Any, str], goal_value: Any
) -> tuple[Learnt, dict[str, Any]] | None:
    """The setting a typed entry showed (its first and last screens), as a variable typed on
    the keypad — or None when the display did not end on the value typed. Shared by the
    finder's two ways to type a missing setting: after an entry key, and after re-entering
    a procedure."""
    kind, typed, value, fmt = typing
    learnt = infer_setting(name, [texts[0], texts[-1]], kind, texts[-1])
    if learnt is None or learnt.current != value or not _fits(learnt.variable, goal_value):
        return None
    variable = dict(learnt.variable)
    variable.pop("wrap", None)
    if kind == "numeric":
        width = max(len(typed), len(str(_whole(variable["initial"]) or "")))
        variable["entry"] = {"format": fmt, "max_digits": width}
    else:
        variable["entry"] = {"format": fmt}
    return learnt, variable
