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
from typing import Literal

from pydantic import Field, model_validator

from apbot.model.machine import (
    Add,
    AnywhereStep,
    Condition,
    Conditional,
    Cycle,
    Effect,
    EffectName,
    GoTo,
    Guard,
    OtherThan,
    Skip,
    Step,
)
from apbot.model.schema_base import (
    IDENT,
    Box,
    ControlKind,
    EntryFormat,
    Ident,
    Scalar,
    Signal,
    Skill,
    TimeStyle,
    _Strict,
)
from apbot.model.variables import (
    DiscreteCase,
    DiscreteVariable,
    Entry,
    NonEmptyStrings,
    NumericCase,
    NumericVariable,
    RangeSpec,
    TimeCase,
    TimeRangeSpec,
    TimeVariable,
    Variable,
    time_step_seconds,
)

__all__ = [
    "IDENT",
    "TEMPLATE_FIELD",
    "Action",
    "Add",
    "AnywhereStep",
    "Appliance",
    "ApplianceModel",
    "Box",
    "Condition",
    "Conditional",
    "Control",
    "ControlKind",
    "Cycle",
    "DiscreteCase",
    "DiscreteVariable",
    "Display",
    "Effect",
    "EffectName",
    "Entry",
    "EntryFormat",
    "GoTo",
    "Guard",
    "Ident",
    "NonEmptyStrings",
    "NumericCase",
    "NumericVariable",
    "OtherThan",
    "RangeSpec",
    "Scalar",
    "Signal",
    "Skill",
    "Skip",
    "Step",
    "TimeCase",
    "TimeRangeSpec",
    "TimeStyle",
    "TimeVariable",
    "Variable",
    "time_step_seconds",
]


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
