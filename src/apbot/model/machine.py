"""The model's machine as data: effects (go-to, add, skip, conditional), feature steps,
``anywhere`` keys, guards and self-ending cycles.

Kept apart from :mod:`apbot.model.schema` (the whole model) and :mod:`apbot.model.variables`
because these say how keys change values, which the simulator compiles
(:mod:`apbot.sim.compiler`), while variables say which values exist.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import Field, field_validator

from apbot.model.schema_base import Ident, Scalar, Signal, _Strict
from apbot.model.values import Number

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


Conditional.model_rebuild()
