"""Infer a variable's true definition from an exploration trace — by code, not by an LLM.

Exploration presses one action repeatedly and records the value shown after each press, until
a value repeats. A value repeating right away means an end was hit (clamp); repeating an
earlier one means the values went round (wrap). From one or two such traces this module
recovers the order of the values, piecewise ranges and their steps, and wrap vs clamp.

>>> order_from_traces([0, 10, 20, 30, 0], None)
Order(values=[0, 10, 20, 30], wrap=True, complete=True)
>>> ranges_from_values([0, 10, 20, 30, 60, 90])
[(0, 30, 10), (30, 90, 30)]
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from itertools import pairwise
from math import gcd
from typing import Any


@dataclass(frozen=True)
class Order:
    """Values in the order the explored action visits them.

    ``wrap`` is None when the trace never showed what happens at an end; ``complete`` is
    False when values may exist that were never shown (one direction explored up to a clamp,
    or the display went dark part of the way).
    """

    values: list[Any]
    wrap: bool | None
    complete: bool


def order_from_traces(forward: Sequence[Any], backward: Sequence[Any] | None) -> Order:
    """The value order seen under an action, from its trace (and its opposite's, after a clamp).

    ``forward`` holds the values shown press after press and ends with the first repeat (or
    where the walk had to stop). ``backward`` is the opposite action's trace started where
    ``forward`` stopped.

    >>> order_from_traces(["low", "mid", "high", "high"], ["high", "mid", "low", "min", "min"])
    Order(values=['min', 'low', 'mid', 'high'], wrap=False, complete=True)
    >>> order_from_traces(["3", "4", "4"], ["4", "3", "2", "1"])  # "1" was the last one shown
    Order(values=['1', '2', '3', '4'], wrap=False, complete=False)
    >>> order_from_traces(["a", "b", "c"], None)  # no repeat: the walk was cut short
    Order(values=['a', 'b', 'c'], wrap=None, complete=False)
    """
    if len(forward) < 2:
        return Order(list(forward), None, False)
    last = forward[-1]
    if last == forward[-2]:  # clamped at the end in this direction
        seen = _unique(forward[:-1])
        if backward and len(backward) >= 2 and backward[-1] == backward[-2]:
            down = _unique(backward[:-1])
            return Order(list(reversed(down)), False, True)
        if backward:  # walked back without reaching the other end (the display went dark)
            below = [v for v in _unique(backward) if v not in seen]
            return Order(list(reversed(below)) + seen, False, False)
        return Order(seen, False, False)
    if last not in forward[:-1]:
        return Order(_unique(forward), None, False)
    first = forward.index(last)
    return Order(_unique(forward[first:-1]), True, True)


def splice(known: Sequence[Any], segment: Sequence[Any]) -> list[Any]:
    """``known`` with ``segment`` (observed, contiguous, in order) written over it: values the
    walk did not reach keep their places around it.

    >>> splice(["off", "a", "x", "b", "c", "d"], ["a", "b", "c"])
    ['off', 'a', 'b', 'c', 'x', 'd']
    """
    observed = set(segment)
    rest = [v for v in known if v not in observed]
    anchor = next((v for v in segment if v in known), None)
    if anchor is None:
        return list(segment) + rest
    position = sum(1 for v in known[: list(known).index(anchor)] if v not in observed)
    return rest[:position] + list(segment) + rest[position:]


class Dark:
    """A press after which the display showed nothing for the variable (an OFF position).

    Every instance is distinct, so two dark presses never look like a repeated value.
    """

    def __repr__(self) -> str:
        return "(dark)"


@dataclass(frozen=True)
class Unread:
    """A press after which the display showed text the belief's display rules cannot print.

    Two equal texts are the same slot (the walk went round); once the display rules are
    repaired the text is read again, and until then it counts as :class:`Dark`.
    """

    text: str

    def __repr__(self) -> str:
        return f"(unread {self.text!r})"


def fill_dark(values: Sequence[Any], known: Sequence[Any], wrap: bool | None) -> list[Any]:
    """Replace runs of :class:`Dark` by the believed values that lie between their neighbours
    (in order, skipping values seen elsewhere); a run with no such values is dropped.

    >>> fill_dark(["a", "b", Dark(), "c"], ["a", "b", "off", "x", "c"], False)
    ['a', 'b', 'off', 'c']
    """
    seen = {v for v in values if not isinstance(v, Dark)}
    result: list[Any] = []
    n = len(values)
    i = 0
    while i < n:
        if not isinstance(values[i], Dark):
            result.append(values[i])
            i += 1
            continue
        j = i
        while j < n and isinstance(values[j], Dark):
            j += 1
        before = values[i - 1] if i > 0 else (values[-1] if wrap else None)
        after = values[j] if j < n else (values[0] if wrap else None)
        between = [v for v in _between(known, before, after, wrap) if v not in seen]
        if not between:  # the belief's order is no help: any value never seen will do
            between = [v for v in known if v not in seen and v not in result]
        result.extend(between[: j - i])
        i = j
    return result


def _between(known: Sequence[Any], before: Any, after: Any, wrap: bool | None) -> list[Any]:
    order = list(known)
    if before in order and after in order:
        start, stop = order.index(before), order.index(after)
        if start < stop:
            return order[start + 1 : stop]
        return order[start + 1 :] + order[:stop] if wrap else []
    if before in order:
        return order[order.index(before) + 1 :]
    if after in order:
        return order[: order.index(after)]
    return []


def _unique(values: Sequence[Any]) -> list[Any]:
    return list(dict.fromkeys(values))


def ranges_from_values(values: Sequence[float]) -> list[tuple[float, float, float]]:
    """Piecewise ``(from, to, step)`` ranges that produce exactly these sorted values.

    >>> ranges_from_values([5])
    [(5, 5, 1)]
    >>> ranges_from_values([1, 2, 3, 5, 7, 8])
    [(1, 3, 1), (3, 7, 2), (7, 8, 1)]
    >>> ranges_from_values([0.1 * i for i in range(6)])
    [(0, 0.5, 0.1)]
    """
    points = sorted({_tidy(round(v, 9)) for v in values})  # 0.1 steps sum to 0.30000000000000004
    if len(points) == 1:
        return [(points[0], points[0], 1)]
    ranges: list[tuple[float, float, float]] = []
    start = points[0]
    step = points[1] - points[0]
    step = _tidy(round(step, 9))
    for previous, current in pairwise(points[1:]):
        change = _tidy(round(current - previous, 9))
        if change != step:
            ranges.append((start, previous, step))
            start, step = previous, change
    ranges.append((start, points[-1], step))
    return ranges


def common_step(numbers: Sequence[float]) -> float:
    """The largest step that divides every difference (for widening a keypad domain).

    >>> common_step([0, 30, 90]), common_step([1.5, 2.0])
    (30, 0.5)
    """
    scale = 1000
    ints = [round(n * scale) for n in numbers]
    step = 0
    for a, b in pairwise(ints):
        step = gcd(step, abs(b - a))
    if step == 0:
        return 1
    result = step / scale
    return int(result) if result == int(result) else result


def typical_change(trace: Sequence[float]) -> float | None:
    """The most common change between successive values (for an ``add`` action)."""
    changes = [b - a for a, b in pairwise(trace) if b != a]
    if not changes:
        return None
    # +1 and -1 as common (two values that wrap): upwards, the way a key usually walks
    return max(changes, key=lambda c: (changes.count(c), -abs(c), c > 0))


def _tidy(number: float) -> float:
    """Whole numbers as ints, so ranges read ``(10, 30, 1)`` rather than ``(10.0, 30.0, 1.0)``."""
    return int(number) if float(number).is_integer() else number


_VALUE_CHARS = ".,:-+"


def infer_template(
    mains: Sequence[str],
    render: Any,
    parse: Any,
    words: bool = False,
    known: Any = None,
    bare: bool = True,
    backtrack: bool = False,
) -> str | None:
    """The display template (``"PL{value}"``) behind texts that show one setting with
    different values: the common start and end are the template's own text, the part that
    varies is the value. ``parse`` reads a value from the varying part (None if it is none)
    and ``render`` prints a value as the model would; the template must give back every text.
    ``words``: the values are words (a discrete setting), not numbers or times. With a single
    text, ``known`` is the value it is believed to show; else (``bare``) a text that is a whole
    value printed alone reads as that value.
    ``backtrack``: the shared start may reach into the value ("1/2+0." of "1/2+0.7" and
    "1/2+0.3"), so shorter starts are tried too — for a ``parse`` that takes only real values.

    >>> infer_template(["PL7", "PL8"], str, lambda t: int(t) if t.isdigit() else None)
    'PL{value}'
    >>> infer_template(["TEMP 180°C", "TEMP 190°C"], lambda v: f"{v}°C",
    ...                lambda t: int(t[:-2]) if t[:-2].isdigit() else None)
    'TEMP {value}'
    >>> infer_template(["PROG fast", "PROG fine"], str, str, words=True)
    'PROG {value}'
    >>> infer_template(["12"], str, lambda t: int(t) if t.isdigit() else None, known=7)
    '{value}'
    >>> infer_template(["LOWER"], str, str, words=True, known="lower")
    '{value}'
    >>> clock = lambda v: f"{v // 60}:{v % 60:02d}"
    >>> infer_template(["00:07"], clock, lambda t: None, known=7) is None  # not "0{value}"
    True
    """
    texts = list(dict.fromkeys(mains))

    def inside(char: str) -> bool:  # could be part of a value
        return char.isalnum() if words else (char.isdigit() or char in _VALUE_CHARS)

    if len(texts) == 1 and known is not None:
        # in any case, as the display reader reads it ("LOWER" shows the value lower)
        printed, text = render(known).lower(), texts[0].lower()
        if len(text) == len(texts[0]) and text.count(printed) == 1:
            start = text.index(printed)
            head, tail = texts[0][:start], texts[0][start + len(printed) :]
            # not inside a longer value ("0:07" in "00:07" is no "0{value}")
            if not (head and inside(head[-1])) and not (tail and inside(tail[0])):
                return head + "{value}" + tail
    if len(texts) == 1 and bare and not words:
        # one text that is a whole value in the setting's notation ("12:00"): a panel that
        # prints the value alone (kept while the digits typed are no value yet)
        value = parse(texts[0])
        if value is not None and render(value) == texts[0]:
            return "{value}"
    if len(texts) < 2:
        return None
    prefix = _common_prefix(texts)
    suffix = _common_prefix([t[len(prefix) :][::-1] for t in texts])[::-1]
    while prefix and inside(prefix[-1]):
        prefix = prefix[:-1]  # do not cut into the value ("TEMP 1" of "TEMP 180")
    while suffix and inside(suffix[0]):
        suffix = suffix[1:]
    leads = [prefix[:end] for end in range(len(prefix), -1, -1)] if backtrack else [prefix]
    for lead in leads:
        for cut in range(len(suffix) + 1):  # a unit the model prints with the value moves in
            tail = suffix[cut:]
            values = [parse(t[len(lead) : len(t) - len(tail)]) for t in texts]
            if all(v is not None for v in values) and all(
                lead + render(v) + tail == t for v, t in zip(values, texts, strict=True)
            ):
                return lead + "{value}" + tail
    return None


def _common_prefix(texts: Sequence[str]) -> str:
    first = texts[0]
    end = 0
    while end < len(first) and all(len(t) > end and t[end] == first[end] for t in texts):
        end += 1
    return first[:end]
