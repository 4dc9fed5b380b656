"""The ordered value domain of a variable, and the one function that normalises a value to it.

Every variable (or every case of a programme-dependent one) has a :class:`Domain`: its values
in button order, the initial one, and whether stepping past an end wraps or clamps.
"""

from __future__ import annotations

import itertools
import math
from bisect import bisect_left, bisect_right
from collections.abc import Container, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

from apbot.model.limits import MAX_MODEL_VALUES, MAX_VALUES, SIZE_LIMITS_DOC
from apbot.model.schema import (
    DiscreteCase,
    DiscreteVariable,
    NumericCase,
    NumericVariable,
    TimeCase,
    TimeVariable,
    time_step_seconds,
)
from apbot.model.values import (
    brief,
    closest_matches,
    expand_ranges,
    format_hms,
    normalise_text,
    parse_hms,
    parse_quantity,
    preview,
    tidy_number,
    unit_of,
)

AnyVariable = DiscreteVariable | NumericVariable | TimeVariable


class DomainError(ValueError):
    """A domain cannot be built (overlapping ranges, an initial value outside it, ...)."""


@dataclass(frozen=True)
class Domain:
    """Values of one variable in order. ``magnitudes`` are numbers (seconds for time)."""

    kind: str
    values: tuple[Any, ...]
    initial: int
    wrap: bool
    magnitudes: tuple[float, ...] | None = None
    index: dict[Any, int] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not self.index:
            object.__setattr__(self, "index", {v: i for i, v in enumerate(self.values)})

    def __len__(self) -> int:
        return len(self.values)

    def next_index(self, i: int) -> int:
        """One step up: wraps to the first value or stays at the last."""
        if i + 1 < len(self.values):
            return i + 1
        return 0 if self.wrap else i

    def prev_index(self, i: int) -> int:
        """One step down: wraps to the last value or stays at the first."""
        if i > 0:
            return i - 1
        return len(self.values) - 1 if self.wrap else i

    @cached_property
    def _period(self) -> float | None:
        """How far a clock counts before it comes round, for evenly spaced magnitudes (None:
        uneven). Worked out once: :meth:`snap_index` needs it for every value of a table."""
        assert self.magnitudes is not None
        mags = self.magnitudes
        steps = {round(b - a, 9) for a, b in itertools.pairwise(mags)}
        if len(steps) != 1:
            return None
        return mags[-1] - mags[0] + steps.pop()

    def snap_index(self, magnitude: float, down: bool = False) -> int:
        """The index reached by adding to a number: the next value at or above ``magnitude``
        (at or below it when subtracting, ``down``), so a key never fails to move the value.

        Past either end a clamping variable stops at the end. A wrapping variable with evenly
        spaced values counts round like a clock (23:30 + 1 h = 00:30); with uneven spacing it
        wraps to the other end.
        """
        assert self.magnitudes is not None
        mags = self.magnitudes
        outside = magnitude > mags[-1] + 1e-9 or magnitude < mags[0] - 1e-9
        if self.wrap and outside and len(mags) > 1:
            period = self._period
            if period is not None:
                magnitude = mags[0] + (magnitude - mags[0]) % period
                outside = False
        if not outside:
            if down:
                i = bisect_right(mags, magnitude + 1e-9) - 1
                return i if i >= 0 else (len(mags) - 1 if self.wrap else 0)
            i = bisect_left(mags, magnitude - 1e-9)
            return i if i < len(mags) else (0 if self.wrap else len(mags) - 1)
        if magnitude < mags[0]:
            return len(mags) - 1 if self.wrap else 0
        return 0 if self.wrap else len(mags) - 1


def range_count(ranges: Sequence[tuple[float, float, float]]) -> int:
    """How many values piecewise ranges give, without listing them (an upper bound when the
    ranges are malformed, which :func:`build_domain` then reports)."""
    count = 0
    for start, stop, step in ranges:
        if not all(math.isfinite(x) for x in (start, stop, step)):
            return MAX_VALUES + 1  # refused as too large, before any arithmetic overflows
        if step > 0 and stop >= start:
            count += min(int((stop - start) / step), MAX_MODEL_VALUES) + 1
    return count


def domain_size(var: AnyVariable, case: Any = None) -> int:
    """Values of a variable's domain (or of one case), counted without building it."""
    spec: Any = case if case is not None else var
    if isinstance(var, DiscreteVariable):
        return len(spec) if isinstance(spec, list) else len(spec.values or [])
    if isinstance(var, NumericVariable):
        return range_count([(float(a), float(b), float(c)) for a, b, c in spec.ranges or []])
    try:
        return range_count(_seconds_ranges(spec))
    except ValueError:
        return 0  # malformed times are reported by the schema


def _seconds_ranges(spec: Any) -> list[tuple[float, float, float]]:
    return [
        (float(parse_hms(a)), float(parse_hms(b)), float(time_step_seconds(c)))
        for a, b, c in spec.ranges or []
    ]


def _too_many(count: int) -> DomainError:
    return DomainError(
        f"{count:,} values; a domain has at most {MAX_VALUES:,} (see {SIZE_LIMITS_DOC})"
    )


def _check_ranges(ranges: list[tuple[float, float, float]], show: Any) -> None:
    previous_end: float | None = None
    for i, (start, stop, step) in enumerate(ranges):
        if not all(math.isfinite(x) for x in (start, stop, step)):
            raise DomainError(f"range {i + 1} is not made of finite numbers")
    count = range_count(ranges)
    if count > MAX_VALUES:
        raise DomainError(
            f"the ranges give {count:,} values; a domain has at most {MAX_VALUES:,} "
            f"(use a coarser step; see {SIZE_LIMITS_DOC})"
        )
    for i, (start, stop, step) in enumerate(ranges):
        if step <= 0:
            raise DomainError(f"range {i + 1} has step {show(step)}; a step must be positive")
        if stop < start:
            raise DomainError(f"range {i + 1} runs backwards ({show(start)} to {show(stop)})")
        span = (stop - start) / step
        if abs(span - round(span)) > 1e-9:
            raise DomainError(
                f"range {i + 1}: {show(stop)} is not reached from {show(start)} in steps of "
                f"{show(step)}; make the end a whole number of steps from the start"
            )
        if previous_end is not None and start < previous_end:
            raise DomainError(
                f"range {i + 1} starts at {show(start)}, inside range {i} (which ends at "
                f"{show(previous_end)}); ranges must not overlap"
            )
        previous_end = stop


_DOMAINS: dict[tuple[int, int], tuple[Any, Any, Domain]] = {}


def build_domain(var: AnyVariable, case: Any = None) -> Domain:
    """The domain of a variable, or of one case of a dependent variable.

    Remembered per (immutable) variable and case object: checking a model and compiling it
    both need every domain, and a 100,000-value one takes a while to build.
    """
    key = (id(var), id(case))
    hit = _DOMAINS.get(key)
    if hit is not None and hit[0] is var and hit[1] is case:
        return hit[2]
    domain = _build_domain(var, case)
    if len(_DOMAINS) >= 64:
        _DOMAINS.pop(next(iter(_DOMAINS)))
    _DOMAINS[key] = (var, case, domain)
    return domain


def _build_domain(var: AnyVariable, case: Any) -> Domain:
    spec: Any = case if case is not None else var
    if isinstance(var, DiscreteVariable):
        if isinstance(spec, list):
            spec = DiscreteCase(values=spec)
        values = list(spec.values or [])
        if len(values) > MAX_VALUES:
            raise _too_many(len(values))
        index: dict[Any, int] = {}
        for i, value in enumerate(values):  # one pass: a list.count per value was quadratic
            if value in index:
                raise DomainError(
                    f"value {value!r} is listed twice (as value {index[value] + 1} and {i + 1})"
                )
            index[value] = i
        initial = spec.initial if spec.initial is not None else values[0]
        if initial not in index:
            raise DomainError(
                f"initial value {initial!r} is not one of {preview(values)}"
                + _did_you_mean(initial, values)
            )
        return Domain("discrete", tuple(values), index[initial], var.wrap, index=index)
    if isinstance(var, NumericVariable):
        assert isinstance(spec, NumericVariable | NumericCase)
        ranges = [(float(a), float(b), float(c)) for a, b, c in spec.ranges or []]
        _check_ranges(ranges, lambda x: f"{tidy_number(x)}")
        numbers = expand_ranges(spec.ranges or [])
        if spec.initial is not None and not math.isfinite(spec.initial):
            raise DomainError(f"initial value {spec.initial} is not a finite number")
        initial = tidy_number(spec.initial) if spec.initial is not None else numbers[0]
        positions = {n: i for i, n in enumerate(numbers)}
        if initial not in positions:
            raise DomainError(f"initial value {initial} is not in the ranges ({_summary(numbers)})")
        return Domain(
            "numeric",
            tuple(numbers),
            positions[initial],
            var.wrap,
            tuple(float(n) for n in numbers),
            index=positions,
        )
    assert isinstance(spec, TimeVariable | TimeCase)
    seconds_ranges = _seconds_ranges(spec)
    _check_ranges(seconds_ranges, lambda s: format_hms(int(s)))
    seconds = [int(s) for s in expand_ranges(seconds_ranges)]
    initial_s = parse_hms(spec.initial) if spec.initial is not None else seconds[0]
    at = {s: i for i, s in enumerate(seconds)}
    if initial_s not in at:
        raise DomainError(
            f"initial value {format_hms(initial_s)} is not in the ranges "
            f"({_summary([format_hms(s) for s in seconds])})"
        )
    return Domain(
        "time",
        tuple(format_hms(s) for s in seconds),
        at[initial_s],
        var.wrap,
        tuple(float(s) for s in seconds),
    )


def case_domains(var: AnyVariable) -> dict[str, Domain]:
    """Domains of a dependent variable by parent value (empty for an independent one)."""
    return {key: build_domain(var, case) for key, case in (var.cases or {}).items()}


def all_values(var: AnyVariable) -> list[Any]:
    """Every value the variable can take in any case, in first-seen order."""
    return list(_values_of(var)[0])


_VALUES: dict[int, tuple[AnyVariable, tuple[Any, ...], frozenset[Any]]] = {}


def _values_of(var: AnyVariable) -> tuple[tuple[Any, ...], frozenset[Any]]:
    """``all_values`` and its set, remembered per (immutable) variable object: goals and
    feedback are normalised after every action, and a clock has 1440 values to rebuild."""
    hit = _VALUES.get(id(var))
    if hit is not None and hit[0] is var:
        return hit[1], hit[2]
    if var.depends_on is None:
        values = build_domain(var).values
    else:
        seen: dict[Any, None] = {}
        for domain in case_domains(var).values():
            seen.update(dict.fromkeys(domain.values))
        values = tuple(seen)
    if len(_VALUES) >= 1024:
        _VALUES.pop(next(iter(_VALUES)))
    _VALUES[id(var)] = (var, values, frozenset(values))
    return values, _VALUES[id(var)][2]


def _summary(values: Sequence[Any]) -> str:
    if len(values) <= 8:
        return ", ".join(str(v) for v in values)
    more = f" ({len(values):,} in all)" if len(values) > 50 else ""
    return ", ".join(str(v) for v in values[:4]) + ", ..., " + str(values[-1]) + more


def _did_you_mean(text: Any, options: list[str]) -> str:
    close = closest_matches(str(text), [str(o) for o in options])
    return f"; did you mean {close[0]!r}?" if close else ""


class ValueProblem(ValueError):
    """A value that does not belong to a variable; the message says what would."""


def normalise(var: AnyVariable, raw: Any, domain: Domain | None = None) -> Any:
    """Canonical form of ``raw`` for ``var``, checked against its domain.

    Accepts what people and LLMs write: "30 min" or 30 for a numeric variable in minutes,
    "2 hrs" or "1:30" for a time, "Quick-Wash" for "quick wash", "on"/True for a switch.
    Raises :class:`ValueProblem` naming the closest valid values.

    >>> from apbot.model.schema import NumericVariable
    >>> normalise(NumericVariable(type="numeric", ranges=[(0, 120, 30)], unit="min"), "2 h")
    120
    """
    members: Container[Any]
    if domain is not None:
        ordered, members = domain.values, domain.index
    else:
        ordered, members = _values_of(var)
    if isinstance(var, DiscreteVariable):
        return _normalise_discrete(raw, ordered, members)
    if isinstance(var, NumericVariable):
        number = _to_number(raw, var.unit)
        if number not in members:
            raise ValueProblem(
                f"{number:g}{_unit_suffix(var.unit)} is not one of its values "
                f"({_summary(list(ordered))})"
            )
        return number
    seconds = _to_seconds(raw, var.format)
    value = format_hms(seconds)
    if value not in members:
        raise ValueProblem(f"{value} is not one of its values ({_summary(list(ordered))})")
    return value


def parse_value(var: AnyVariable, raw: Any) -> Any:
    """Canonical form of ``raw`` for ``var``'s type, *not* checked against its domain.

    A display may show a value the model lacks (35 °C when the model has 0..30 in tens); read
    the way the model writes values, it is evidence that the model is wrong. Discrete values
    are the text as shown (stripped). Raises :class:`ValueProblem` when ``raw`` is not a value
    of that type at all.

    >>> from apbot.model.schema import NumericVariable
    >>> parse_value(NumericVariable(type="numeric", ranges=[(0, 30, 10)], unit="°C"), "35°C")
    35
    """
    if isinstance(var, DiscreteVariable):
        text = (str(raw).lower() if isinstance(raw, bool) else str(raw)).strip()
        if not text:
            raise ValueProblem("an empty value")
        return text
    if isinstance(var, NumericVariable):
        return _to_number(raw, var.unit)
    return format_hms(_to_seconds(raw, var.format))


def _unit_suffix(unit: str) -> str:
    return f" {unit}" if unit and unit[0].isalnum() else unit


def _normalise_discrete(raw: Any, ordered: Sequence[str], members: Container[str]) -> str:
    if isinstance(raw, bool):  # a switch reported as True/False, whatever its words are
        words = ("true", "on", "yes") if raw else ("false", "off", "no")
        raw = next((w for w in words if w in members), words[0])
    text = str(raw)
    if text in members:
        return text
    values = list(ordered)
    key = normalise_text(text)
    matches = [v for v in values if normalise_text(v) == key]
    if len(matches) == 1:
        return matches[0]
    quantity = parse_quantity(text)
    if quantity is not None:  # "40 °C" for a value listed as "40"
        by_number = [
            v
            for v in values
            if (q := parse_quantity(v))
            and abs(q[0] - quantity[0]) < 1e-9
            and (q[1] is None or quantity[1] is None or q[1] == quantity[1])
        ]
        if len(by_number) == 1:
            return by_number[0]
    raise ValueProblem(
        f"{brief(text)} is not one of {preview(values)}" + _did_you_mean(text, values)
    )


def _to_number(raw: Any, unit: str) -> int | float:
    """The number ``raw`` stands for, in ``unit``; never infinite or NaN (no domain has them,
    and ``int(inf)`` would be an OverflowError deep inside)."""
    number = _any_number(raw, unit)
    try:
        finite = math.isfinite(number)
    except OverflowError:  # an int too large for a float
        finite = False
    if not finite:
        raise ValueProblem(f"{brief(raw)} is not a finite number")
    return tidy_number(number)


def _any_number(raw: Any, unit: str) -> float:
    if isinstance(raw, bool):
        raise ValueProblem(f"expected a number, got {brief(raw)}")
    if isinstance(raw, int | float):
        return raw
    text = str(raw).strip()
    if unit and text.casefold().endswith(unit.casefold()):
        # the variable's own unit, whatever it is ("2.5 lb", "3 cups", "1200 W")
        bare = parse_quantity(text[: len(text) - len(unit)].strip())
        if bare is not None and bare[1] is None:
            return round(bare[0], 6)
    quantity = parse_quantity(text)
    if quantity is None:
        raise ValueProblem(f"{brief(raw)} is not a number" + (f" of {unit}" if unit else ""))
    number, dimension, _ = quantity
    if dimension is not None:
        target = unit_of(unit) if unit else None
        if target is None:
            if unit:
                raise ValueProblem(f"cannot convert {brief(raw)} to {unit!r}")
        elif target[0] != dimension:
            raise ValueProblem(f"{brief(raw)} is not a quantity in {unit}")
        else:
            number = number / target[1]
    return round(number, 6)


def _to_seconds(raw: Any, style: str) -> int:
    text = str(raw).strip()
    if isinstance(raw, int | float) and not isinstance(raw, bool):
        raise ValueProblem(
            f"a bare number {brief(raw)} is ambiguous for a time; write 00:30:00, '30 min' or '2 h'"
        )
    parts = text.split(":")
    if len(parts) == 3 and all(p.isdigit() for p in parts):
        try:
            return parse_hms(text)
        except ValueError:
            raise ValueProblem(
                f"{brief(text)} is not a time (minutes and seconds go up to 59)"
            ) from None
    if len(parts) == 2 and all(p.isdigit() for p in parts):
        first, second = int(parts[0]), int(parts[1])
        if second >= 60:
            raise ValueProblem(f"{brief(text)} is not a time")
        # mm:ss on a display showing minutes and seconds, else h:mm
        return first * 60 + second if style == "mm:ss" else first * 3600 + second * 60
    quantity = parse_quantity(text)
    if quantity is None or quantity[1] not in ("time", None):
        raise ValueProblem(f"{brief(text)} is not a duration (try '90 min' or 01:30:00)")
    if quantity[1] is None:
        raise ValueProblem(f"a bare number {brief(text)} is ambiguous for a time; give a unit")
    seconds = quantity[0]
    if not math.isfinite(seconds):
        raise ValueProblem(f"{brief(text)} is not a finite duration")
    if abs(seconds - round(seconds)) > 1e-6:
        raise ValueProblem(f"{brief(text)} is not a whole number of seconds")
    return round(seconds)


def marked_unreachable(var: AnyVariable) -> frozenset[Any]:
    """The canonical values a variable declares ``unreachable`` (ones that normalise to none of
    its values are left out here; the checker reports them)."""
    found = set()
    for raw in var.unreachable:
        try:
            found.add(normalise(var, raw))
        except ValueProblem:
            continue
    return frozenset(found)
