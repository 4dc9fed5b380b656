"""The ground every part of the model schema stands on: strict records (unknown keys are
errors) and the small shared types — identifiers, the literal vocabularies, scalars.

Kept apart from :mod:`apbot.model.schema` so that the variable kinds
(:mod:`apbot.model.variables`) and the machine's parts (:mod:`apbot.model.machine`) can use
them without importing the whole model.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

IDENT = r"^[a-z][a-z0-9_]*$"
Ident = Annotated[str, Field(pattern=IDENT)]
Box = tuple[int, int, int, int]

ControlKind = Literal["button", "dial", "key", "touch", "switch", "knob"]
Skill = Literal["press", "hold", "turn_cw", "turn_ccw", "wait"]
TimeStyle = Literal["hh:mm:ss", "mm:ss", "h:mm", "hh:mm", "min", "h", "s"]
EntryFormat = Literal["mm:ss", "hh:mm", "h:mm", "hh:mm:ss", "minutes", "seconds", "number"]
Scalar = str | int | float | bool
Signal = Literal["beep", "silent"]  # how a refused key makes itself known, if at all


class _Strict(BaseModel):
    """Unknown keys are errors: a typo in a model must not pass silently. Numbers are finite
    (YAML reads ``.inf`` and ``.nan`` as floats; no appliance has an infinite range)."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)
