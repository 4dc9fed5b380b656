"""The appliance model as data: a pydantic v2 schema loaded from YAML or JSON.

A model is a symbolic state machine written down as plain data — never code — so that an
LLM's answer can be validated and a bad one explained, and so that one engine (``apbot.sim``)
runs every model the same way. The paper had the LLM write a Python simulator and executed it;
we never execute text produced by an LLM.

Shape of a model (see ``apbot/data/examples`` for complete ones)::

    appliance: {id: rice_cooker_2, category: rice_cooker, name: "..."}
    controls: [{id: menu_button, kind: button, label: MENU}]
    variables:
      menu: {type: discrete, values: [white rice, brown rice], initial: white rice}
      delay: {type: numeric, unit: min, ranges: [[0, 60, 10], [60, 720, 30]], initial: 0}
    actions:
      press_menu: {control: menu_button}
    features:
      set_menu: [{actions: [press_menu], variable: menu, effect: next}]
    guards:
      - {when: {power: "off"}, only: [press_power], display: ""}

Semantics: what an effect does to a value in ``apbot.model.effects``; the machine (the feature
pointer, guards, cycles) in ``apbot.sim.compiled``.
"""

from __future__ import annotations

import re
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from apbot.model.values import Number, parse_hms

IDENT = r"^[a-z][a-z0-9_]*$"
Ident = Annotated[str, Field(pattern=IDENT)]
Box = tuple[int, int, int, int]

ControlKind = Literal["button", "dial", "key", "touch", "switch", "knob"]
Skill = Literal["press", "hold", "turn_cw", "turn_ccw", "wait"]
TimeStyle = Literal["hh:mm:ss", "mm:ss", "h:mm", "hh:mm", "min", "h"]
EntryFormat = Literal["mm:ss", "hh:mm", "h:mm", "hh:mm:ss", "minutes", "seconds", "number"]
Scalar = str | int | float | bool
Signal = Literal["beep", "silent"]  # how a refused key makes itself known, if at all


class _Strict(BaseModel):
    """Unknown keys are errors: a typo in a model must not pass silently. Numbers are finite
    (YAML reads ``.inf`` and ``.nan`` as floats; no appliance has an infinite range)."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class Appliance(_Strict):
    """Who the model describes."""

    id: Ident
    category: Ident
    name: str = ""
    brand: str = ""


class Control(_Strict):
    """A physical element of the panel. ``box`` is in panel-image pixels when known."""

    id: Ident
    kind: ControlKind = "button"
    label: str = ""
    box: Box | None = None


class Action(_Strict):
    """One physical action: press, hold (for ``seconds``; two controls together) or a dial turn.

    ``digit`` marks a keypad key: a step whose effect is ``digit`` appends it to the input buffer.
    ``skill: wait`` is no touch at all: ``seconds`` without a key, which lets a step's
    ``timeout`` expire. ``too_short: enters`` says that a hold released early still moves the
    procedure on (only the change needs the full hold); by default it is ignored.
    """

    control: Ident | None = None
    controls: list[Ident] | None = None
    skill: Skill = "press"
    seconds: float | None = Field(default=None, gt=0)
    digit: int | None = Field(default=None, ge=0, le=9)
    too_short: Literal["ignored", "enters"] = "ignored"

    @model_validator(mode="after")
    def _one_way_to_name_controls(self) -> Action:
        if self.skill == "wait":
            if self.control is not None or self.controls is not None:
                raise ValueError("a wait touches no control: give only `seconds`")
            if self.seconds is None:
                raise ValueError("a wait needs `seconds` (how long nothing is pressed)")
            if self.digit is not None:
                raise ValueError("a wait is not a keypad digit")
            return self
        if self.too_short != "ignored" and self.skill != "hold":
            raise ValueError("`too_short` only applies to holds")
        if (self.control is None) == (self.controls is None):
            raise ValueError("give either `control` (one) or `controls` (a two-control hold)")
        if self.controls is not None:
            if self.skill != "hold":
                raise ValueError("only a hold can use two controls together (`controls`)")
            if len(self.controls) != 2 or self.controls[0] == self.controls[1]:
                raise ValueError("a two-control hold names exactly two different controls")
        if self.skill == "hold" and self.seconds is None:
            raise ValueError("a hold needs `seconds` (how long the control must be held)")
        if self.skill != "hold" and self.seconds is not None:
            raise ValueError(f"`seconds` only applies to holds and waits, not to {self.skill}")
        return self

    @property
    def control_ids(self) -> list[str]:
        """The controls this action touches (none for a wait)."""
        if self.skill == "wait":
            return []
        return list(self.controls) if self.controls else [self.control or ""]


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

EffectName = Literal["next", "prev", "toggle", "digit", "clear", "reset", "none"]


class GoTo(_Strict):
    """Go-to effect: the action sets the variable to one value (e.g. a POPCORN key)."""

    to: Scalar


class Add(_Strict):
    """Add (or with a negative amount, subtract) a fixed amount, e.g. a "+30 SEC" key.

    The result snaps to the next value of the domain in the direction of the change; past an
    end it wraps or clamps. Time amounts are seconds or ``HH:MM:SS`` (``-HH:MM:SS`` to subtract).
    """

    add: Number | str


class Skip(_Strict):
    """Move several values along the variable's order at once (negative: back), each move
    wrapping or clamping as ``next``/``prev`` do: a held ▲ that scrolls five menus at a time,
    or a long range crossed in bigger strides."""

    skip: int

    @field_validator("skip")
    @classmethod
    def _not_zero(cls, value: int) -> int:
        if value == 0:
            raise ValueError("skip 0 changes nothing; use `none`")
        return value


class OtherThan(_Strict):
    """A condition on every value but these: ``{other_than: "off"}`` (a dial anywhere but OFF)."""

    other_than: Scalar | list[Scalar]


Condition = Scalar | list[Scalar] | OtherThan  # one value, any of a list, or any but these


def _condition_strings(value: Any) -> Any:
    """Conditions compare with written values: YAML's ``on``/``off`` booleans become strings."""
    if not isinstance(value, dict):
        return value

    def fix(item: Any) -> Any:
        return str(item).lower() if isinstance(item, bool) else item

    def fix_all(item: Any) -> Any:
        if isinstance(item, list):
            return [fix(i) for i in item]
        if isinstance(item, dict) and "other_than" in item:
            return {**item, "other_than": fix_all(item["other_than"])}
        return fix(item)

    return {k: fix_all(v) for k, v in value.items()}


class Conditional(_Strict):
    """An effect that depends on the state before the press: ``then`` while every condition
    in ``when`` holds (as in a guard), else ``otherwise`` — a START/+30 s key that adds 30 s
    when no time is set. Branches are value changes (no keypad digits); they may nest."""

    when: dict[Ident, Condition] = Field(min_length=1)
    then: Effect
    otherwise: Effect = "none"

    @field_validator("when", mode="before")
    @classmethod
    def _when_strings(cls, value: Any) -> Any:
        return _condition_strings(value)


Effect = EffectName | GoTo | Add | Skip | Conditional


class Step(_Strict):
    """One step of a feature (macro action): the actions that belong to it and what they do.

    ``effect`` is one effect for every action of the step, or a map from action to effect.
    ``set`` and ``reset`` are side effects applied by every accepted action of the step.
    ``on_entry: show`` makes the action that enters the step only show the current value
    ("press TEMP to see the setting, press again to change it"); by default it also applies.
    ``optional`` lets the procedure skip the step: from the step before it, the actions of the
    step after it are accepted too. ``timeout`` is how many seconds without a key return the
    appliance from this step to no feature (a ``wait`` action lets that happen).
    """

    actions: list[Ident]
    variable: Ident | None = None
    effect: Effect | dict[Ident, Effect] | None = None
    on_entry: Literal["apply", "show"] = "apply"
    set: dict[Ident, Scalar] = Field(default_factory=dict)
    reset: list[Ident] = Field(default_factory=list)
    note: str = ""
    optional: bool = False
    timeout: float | None = Field(default=None, gt=0)

    @field_validator("set", mode="before")
    @classmethod
    def _set_strings(cls, value: Any) -> Any:
        return _set_strings(value)


def _set_strings(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: (str(v).lower() if isinstance(v, bool) else v) for k, v in value.items()}
    return value


class AnywhereStep(_Strict):
    """Keys that act from any screen without moving the procedure (START, a lock hold, STOP).

    Like a step (``actions``, ``variable``, ``effect``, ``set``, ``reset``) but belonging to no
    feature: the feature pointer stays where it is — or, with ``leave``, returns to no
    feature (CANCEL) — and a half-typed keypad buffer empties.
    """

    actions: list[Ident]
    variable: Ident | None = None
    effect: Effect | dict[Ident, Effect] | None = None
    set: dict[Ident, Scalar] = Field(default_factory=dict)
    reset: list[Ident] = Field(default_factory=list)
    leave: bool = False
    note: str = ""

    @field_validator("set", mode="before")
    @classmethod
    def _set_strings(cls, value: Any) -> Any:
        return _set_strings(value)


class Guard(_Strict):
    """A global condition checked before any action (power off, child lock, running).

    While every condition in ``when`` holds (a value, or a list meaning any of them), only the
    actions in ``only`` are accepted; the others are refused and the display shows ``display``
    (when it is not empty). With ``hide``, the display shows ``display`` for as long as the
    guard holds (a switched-off appliance is dark), not only when an action is refused.
    ``signal`` says whether a refusal can be perceived: ``beep`` (a sound, a flashing message)
    or ``silent`` (the key just does nothing); see :meth:`refusal_signal` for the default.
    """

    name: str = ""
    when: dict[Ident, Condition] = Field(min_length=1)
    only: list[Ident]
    display: str = ""
    hide: bool = False
    signal: Signal | None = None

    def refusal_signal(self) -> Signal:
        """How a refused key makes itself known: as declared, else a beep when the guard shows
        a message ("LOCKED") and nothing when it does not (a dark panel ignores keys)."""
        if self.signal is not None:
            return self.signal
        return "beep" if self.display.strip() else "silent"

    @field_validator("when", mode="before")
    @classmethod
    def _when_strings(cls, value: Any) -> Any:
        return _condition_strings(value)


class Cycle(_Strict):
    """A cycle that ends by itself: while ``when`` holds (running is on) for as long as the
    variable ``lasts`` says (a time, or a number in s, min or h), then ``set`` and ``reset``
    apply as a step's side effects do (running off, the timer back to its default).

    Time passes only when the simulator is told to wait (:meth:`Simulator.wait`); presses
    take no time, so the planner plans presses and a cycle never ends during a plan.
    """

    name: str = ""
    when: dict[Ident, Condition] = Field(min_length=1)
    lasts: Ident
    set: dict[Ident, Scalar] = Field(default_factory=dict)
    reset: list[Ident] = Field(default_factory=list)

    @field_validator("when", mode="before")
    @classmethod
    def _when_strings(cls, value: Any) -> Any:
        return _condition_strings(value)

    @field_validator("set", mode="before")
    @classmethod
    def _set_strings(cls, value: Any) -> Any:
        if isinstance(value, dict):
            return {k: (str(v).lower() if isinstance(v, bool) else v) for k, v in value.items()}
        return value


class Display(_Strict):
    """What the display shows when no variable is being adjusted, and its permanent icons.

    ``idle`` is a template over variable names, e.g. ``"{cook_time}"`` or ``"READY"``.
    ``indicators`` are variables always visible (lamps, icons: child lock, running): each is
    shown after the main text as its lamp (see ``apbot.sim.simulator.lamp_text``).
    ``ignored`` is what a key that does nothing in the current state does: most panels ignore
    it without a sign (``silent``); some beep (``beep``). A too-short hold counts as such a key.
    """

    idle: str = ""
    indicators: list[Ident] = Field(default_factory=list)
    ignored: Signal = "silent"


class ApplianceModel(_Strict):
    """A whole appliance model. Field order is the order of a well-written model file."""

    appliance: Appliance
    controls: list[Control] = Field(min_length=1)
    variables: dict[Ident, Variable] = Field(min_length=1)
    actions: dict[Ident, Action] = Field(min_length=1)
    features: dict[Ident, list[Step]] = Field(min_length=1)
    anywhere: list[AnywhereStep] = Field(default_factory=list)
    guards: list[Guard] = Field(default_factory=list)
    display: Display = Field(default_factory=Display)
    cycles: list[Cycle] = Field(default_factory=list)

    def control(self, control_id: str) -> Control | None:
        """The control with this id, if any."""
        return next((c for c in self.controls if c.id == control_id), None)


TEMPLATE_FIELD = re.compile(r"\{([a-z][a-z0-9_]*)\}")

Conditional.model_rebuild()
