"""Values as numbers and back: the arithmetic the explorer and the loop share.

Times are compared as seconds, numbers as floats; :func:`canonical` writes a number back in the
model's notation (``HH:MM:SS`` for a time).
"""

from __future__ import annotations

from typing import Any

from apbot.model.domain import ValueProblem, parse_value
from apbot.model.schema import TimeVariable
from apbot.model.values import format_hms, parse_hms

__all__ = ["canonical", "loose", "magnitude", "summary", "tidy"]


def magnitude(spec: Any, value: Any) -> float | None:
    """A numeric or time value as a number (seconds for times); None for anything else."""
    if value is None:
        return None
    try:
        if isinstance(spec, TimeVariable):
            return float(parse_hms(str(value)))
        return float(value)
    except (TypeError, ValueError):
        return None


def loose(spec: Any, raw: Any) -> Any:
    """``raw`` in canonical form for ``spec``'s type, whether or not its domain has it."""
    try:
        return parse_value(spec, raw)
    except ValueProblem:
        return None


def canonical(spec: Any, number: float | None) -> Any:
    """A number back in the model's notation (``HH:MM:SS`` for times)."""
    if number is None:
        return None
    if isinstance(spec, TimeVariable):
        return format_hms(int(number))
    return tidy(number)


def tidy(number: float) -> int | float:
    return int(number) if float(number).is_integer() else number


def summary(values: list[Any] | None) -> str:
    if not values:
        return "nothing"
    shown = [str(v) for v in values]
    return ", ".join(shown) if len(shown) <= 12 else ", ".join(shown[:10]) + f", … ({len(shown)})"
