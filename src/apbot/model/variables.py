"""The model's variables as data: the three kinds (discrete, numeric, time), their
programme-dependent cases and keypad entry, and the checks that a variable's domain is given
exactly once.

Kept apart from :mod:`apbot.model.schema` (the whole model) because a variable's fields and
their checks are the largest part of the schema and the part most code reads on its own.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, field_validator, model_validator

from apbot.model.schema_base import EntryFormat, Ident, Scalar, TimeStyle, _Strict
from apbot.model.values import Number, parse_hms


class Entry(_Strict):
    """How keypad digits typed into a buffer become a value.

    Digits shift in from the right, as on a microwave: with ``mm:ss``, typing 1, 3, 0 shows
    ``01:30``. ``overflow`` says what happens once ``max_digits`` are typed: ``shift`` drops
    the oldest digit, ``ignore`` drops the new one. ``other_keys: clear`` empties the buffer
    when a non-digit key of the typing step is pressed (the value stays as typed).
    ``shows: typed`` makes the display show the digits as typed, in the entry format, while
    the buffer holds any (``00:00:80`` on the way to ``00:08:00``), instead of the value.
    """

    format: EntryFormat
    max_digits: int | None = Field(default=None, ge=1, le=8)
    overflow: Literal["shift", "ignore"] = "shift"
    other_keys: Literal["keep", "clear"] = "keep"
    shows: Literal["value", "typed"] = "value"

    def digits(self) -> int:
        """The buffer length: declared, or the format's natural width."""
        if self.max_digits is not None:
            return self.max_digits
        return {"mm:ss": 4, "hh:mm": 4, "h:mm": 3, "hh:mm:ss": 6}.get(self.format, 4)


RangeSpec = tuple[Number, Number, Number]
TimeRangeSpec = tuple[str, str, int | str]


def time_step_seconds(step: int | str) -> int:
    """A time amount given as seconds (60, -30) or as ``HH:MM:SS`` ("00:01:00", "-00:00:30")."""
    if isinstance(step, int):
        return step
    text = str(step).strip()
    return -parse_hms(text[1:]) if text.startswith("-") else parse_hms(text)


def _check_hms(value: str | None) -> str | None:
    if value is not None:
        parse_hms(value)  # raises ValueError with the reason; pydantic reports it at the path
    return value


class DiscreteCase(_Strict):
    values: list[str] = Field(min_length=1)
    initial: str | None = None


class NumericCase(_Strict):
    ranges: list[RangeSpec] = Field(min_length=1)
    initial: Number | None = None


class _TimeChecks(_Strict):
    """Times written in a model (ranges, initial) must be valid ``HH:MM:SS``."""

    @field_validator("ranges", check_fields=False)
    @classmethod
    def _hms(cls, ranges: list[TimeRangeSpec] | None) -> list[TimeRangeSpec] | None:
        for start, stop, step in ranges or []:
            parse_hms(start), parse_hms(stop), time_step_seconds(step)
        return ranges

    @field_validator("initial", check_fields=False)
    @classmethod
    def _initial_hms(cls, value: str | None) -> str | None:
        return _check_hms(value)


class TimeCase(_TimeChecks):
    ranges: list[TimeRangeSpec] = Field(min_length=1)
    initial: str | None = None


NonEmptyStrings = Annotated[list[str], Field(min_length=1)]


def _stringify(values: Any) -> Any:
    """YAML reads ``- 40`` as an int; discrete values are always strings."""
    if isinstance(values, list):
        return [str(v).lower() if isinstance(v, bool) else str(v) for v in values]
    return values


class _Variable(_Strict):
    """Fields every variable kind shares.

    ``remember`` (with ``depends_on``) keeps the setting's value per programme: choosing
    another programme shows that programme's own last value, not its default.
    ``unreachable`` lists values no key can set — the appliance sets them itself (an automatic
    programme's own stage, a sensor reading) — so the checker accepts them unreached and the
    planner reports a goal on one as unreachable, saying so.
    """

    label: str | None = None
    show: str | dict[str, str] | None = None
    visible: bool = True
    depends_on: Ident | None = None
    remember: bool = False
    unreachable: list[Scalar] = Field(default_factory=list)

    @field_validator("unreachable", mode="before")
    @classmethod
    def _unreachable_strings(cls, values: Any) -> Any:
        if isinstance(values, list):
            return [str(v).lower() if isinstance(v, bool) else v for v in values]
        return values

    def display_label(self, name: str) -> str:
        """What the display calls the variable: its label, or its name in capitals."""
        return self.label if self.label is not None else name.replace("_", " ").upper()


class DiscreteVariable(_Variable):
    """Named values in a fixed order (menus, modes, on/off). Wraps by default, like a mode key."""

    type: Literal["discrete"]
    values: NonEmptyStrings | None = None
    initial: str | None = None
    wrap: bool = True
    cases: dict[str, NonEmptyStrings | DiscreteCase] | None = None

    @field_validator("values", mode="before")
    @classmethod
    def _value_strings(cls, values: Any) -> Any:
        return _stringify(values)

    @field_validator("initial", mode="before")
    @classmethod
    def _initial_str(cls, value: Any) -> Any:
        if isinstance(value, bool):
            return str(value).lower()
        return None if value is None else str(value)

    @field_validator("cases", mode="before")
    @classmethod
    def _case_strings(cls, cases: Any) -> Any:
        if not isinstance(cases, dict):
            return cases
        fixed: dict[str, Any] = {}
        for key, case in cases.items():
            if isinstance(case, dict) and "values" in case:
                case = {**case, "values": _stringify(case["values"])}
                if case.get("initial") is not None:
                    case["initial"] = str(case["initial"])
            fixed[str(key)] = _stringify(case)
        return fixed

    @model_validator(mode="after")
    def _domain_given_once(self) -> DiscreteVariable:
        _check_domain_given_once(self, self.values is not None)
        return self


class NumericVariable(_Variable):
    """A number on piecewise ``[from, to, step]`` ranges with a unit. Clamps by default."""

    type: Literal["numeric"]
    ranges: list[RangeSpec] | None = Field(default=None, min_length=1)
    unit: str = ""
    initial: Number | None = None
    wrap: bool = False
    entry: Entry | None = None
    cases: dict[str, NumericCase] | None = None

    @model_validator(mode="after")
    def _domain_given_once(self) -> NumericVariable:
        _check_domain_given_once(self, self.ranges is not None)
        if self.entry is not None and self.entry.format != "number":
            raise ValueError("a numeric variable's keypad entry format is `number`")
        return self


class TimeVariable(_Variable, _TimeChecks):
    """A duration or clock time, canonical ``HH:MM:SS``, on piecewise ranges of seconds."""

    type: Literal["time"]
    ranges: list[TimeRangeSpec] | None = Field(default=None, min_length=1)
    initial: str | None = None
    wrap: bool = False
    format: TimeStyle = "hh:mm:ss"
    entry: Entry | None = None
    cases: dict[str, TimeCase] | None = None

    @model_validator(mode="after")
    def _domain_given_once(self) -> TimeVariable:
        _check_domain_given_once(self, self.ranges is not None)
        if self.entry is not None and self.entry.format == "number":
            raise ValueError(
                "a time variable's keypad entry is mm:ss, hh:mm, h:mm, hh:mm:ss, minutes or seconds"
            )
        return self


def _check_domain_given_once(var: Any, has_own_domain: bool) -> None:
    if var.depends_on is None:
        if not has_own_domain:
            key = "values" if var.type == "discrete" else "ranges"
            raise ValueError(f"give `{key}` (or `depends_on` with `cases`)")
        if var.cases is not None:
            raise ValueError("`cases` needs `depends_on` (the variable that selects the case)")
    else:
        if has_own_domain:
            raise ValueError("a variable with `depends_on` takes its domains from `cases` only")
        if not var.cases:
            raise ValueError("`depends_on` needs `cases`: one domain per value of the parent")
        if var.initial is not None:
            raise ValueError("a dependent variable's initial value is given per case")


Variable = Annotated[DiscreteVariable | NumericVariable | TimeVariable, Field(discriminator="type")]
