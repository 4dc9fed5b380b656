"""The answer formats of the LLM reader's stages, and their conversion to and from the model.

Each stage's answer is a small pydantic model, simpler than the appliance model (no dicts keyed
by names, no effect vocabulary beyond next / prev / toggle / set / none), so a small model can
fill it and a strict schema can describe it. Conversion to the model format is code; the
assembled model is then checked like any other. The offline reading converts the other way to
give the LLM a draft to correct.
"""

from __future__ import annotations

import itertools
import re
from typing import Any, Literal

from pydantic import BaseModel, Field, TypeAdapter, ValidationError

from apbot.model.domain import DomainError, build_domain
from apbot.model.schema import ApplianceModel, Variable
from apbot.model.values import format_hms, parse_hms

NAME = r"^[a-z][a-z0-9_]*$"


class ControlInfo(BaseModel):
    action: str
    label: str = Field(description="the control's label as the manual writes it")
    does: str = Field(description="what it does, in a few words")


class Controls(BaseModel):
    controls: list[ControlInfo]


class VariableInfo(BaseModel):
    name: str = Field(pattern=NAME)
    kind: Literal["choice", "number", "time", "switch"]
    values: list[str] = Field(default_factory=list, description="choice: the options in order")
    low: str | None = Field(default=None, description="number or time (H:MM:SS): lowest")
    high: str | None = Field(default=None, description="number or time (H:MM:SS): highest")
    step: str | None = Field(default=None, description="number: step; time: step in seconds")
    unit: str = ""
    initial: str | None = None


class Variables(BaseModel):
    variables: list[VariableInfo]


class Press(BaseModel):
    action: str
    effect: Literal["next", "prev", "toggle", "set", "none"]
    value: str | None = Field(default=None, description="for set: the value it selects")


class Assignment(BaseModel):
    variable: str
    value: str


class StepInfo(BaseModel):
    variable: str | None = Field(default=None, description="the setting this step adjusts")
    presses: list[Press] = Field(min_length=1)
    sets: list[Assignment] = Field(default_factory=list, description="settings it also sets")


class FeatureInfo(BaseModel):
    name: str = Field(pattern=NAME)
    steps: list[StepInfo] = Field(min_length=1)


class Features(BaseModel):
    features: list[FeatureInfo]


_VARIABLE = TypeAdapter(Variable)


def _number(text: str | None, what: str) -> float:
    if text is None or not str(text).strip():
        raise ValueError(f"{what} is missing")
    match = re.search(r"-?\d+(?:\.\d+)?", str(text))
    if match is None:
        raise ValueError(f"{what} {text!r} is not a number")
    value = float(match.group())
    return int(value) if value.is_integer() else value


def _hms(text: str | None, what: str) -> str:
    """The answer's time in the model's HH:MM:SS ("1:30:00" -> "01:30:00"), or why not."""
    if text is None:
        raise ValueError(f"{what} is missing")
    try:
        seconds = parse_hms(str(text).strip())
    except ValueError:
        raise ValueError(f"{what} {text!r} is not a time like 1:30:00") from None
    return format_hms(seconds)


def variable_spec(info: VariableInfo) -> dict[str, Any]:
    """The model's variable for one answer entry; ``ValueError`` says what is wrong."""
    if info.kind == "switch":
        initial = info.initial if info.initial in ("off", "on") else "off"
        return {"type": "discrete", "values": ["off", "on"], "initial": initial}
    if info.kind == "choice":
        values = list(dict.fromkeys(v.strip() for v in info.values if v.strip()))
        if len(values) < 2:
            raise ValueError("a choice needs at least two values")
        initial = info.initial if info.initial in values else values[0]
        return {"type": "discrete", "values": values, "initial": initial}
    if info.kind == "number":
        low, high = _number(info.low, "low"), _number(info.high, "high")
        step = _number(info.step or "1", "step")
        spec: dict[str, Any] = {"type": "numeric", "ranges": [[low, high, step]], "initial": low}
        if info.unit.strip():
            spec["unit"] = info.unit.strip()
        return spec
    low_t, high_t = _hms(info.low, "low"), _hms(info.high, "high")
    step_s = int(_number(info.step or "60", "step"))
    style = "h:mm" if parse_hms(high_t) >= 3600 and step_s % 60 == 0 else "mm:ss"
    return {
        "type": "time",
        "ranges": [[low_t, high_t, step_s]],
        "initial": low_t,
        "format": style,
    }


def variable_problems(info: VariableInfo) -> list[str]:
    """Why one variable cannot be used (empty when it can)."""
    try:
        spec = variable_spec(info)
        build_domain(_VARIABLE.validate_python(spec))
    except (ValueError, DomainError) as exc:
        text = exc.errors()[0]["msg"] if isinstance(exc, ValidationError) else str(exc)
        return [f"variables {info.name}: {text}"]
    return []


def step_spec(step: StepInfo) -> dict[str, Any]:
    """The model's step for one answer step."""
    effects: dict[str, Any] = {}
    for press in step.presses:
        if press.effect == "set":
            effects[press.action] = {"to": press.value} if press.value is not None else "none"
        else:
            effects[press.action] = press.effect
    out: dict[str, Any] = {"actions": list(effects)}
    if step.variable:
        out["variable"] = step.variable
        distinct = {str(e) for e in effects.values()}
        out["effect"] = next(iter(effects.values())) if len(distinct) == 1 else effects
    if step.sets:
        out["set"] = {a.variable: a.value for a in step.sets}
    return out


# --- the offline reading as a draft -----------------------------------------------------------


def _effect_of(step: Any, action: str) -> tuple[str, str | None]:
    effect = step.effect
    if isinstance(effect, dict):
        effect = effect.get(action, "none")
    if isinstance(effect, str):
        return (effect if effect in ("next", "prev", "toggle") else "none"), None
    to = getattr(effect, "to", None)
    return ("set", str(to)) if to is not None else ("none", None)


def draft_controls(model: ApplianceModel) -> Controls:
    labels = {c.id: c.label for c in model.controls}
    out = []
    for name, action in model.actions.items():
        ids = [action.control] if action.control else list(action.controls or [])
        label = " + ".join(labels.get(i, i) for i in ids)
        out.append(ControlInfo(action=name, label=label, does=""))
    return Controls(controls=out)


def draft_variables(model: ApplianceModel) -> Variables:
    from apbot.model.domain import all_values

    out = []
    for name, var in model.variables.items():
        values = all_values(var)
        if var.type == "discrete":
            kind: Any = "switch" if sorted(values) == ["off", "on"] else "choice"
            out.append(
                VariableInfo(
                    name=name,
                    kind=kind,
                    values=[] if kind == "switch" else [str(v) for v in values],
                    initial=None if var.initial is None else str(var.initial),
                )
            )
            continue
        ordered = sorted(values, key=lambda v: parse_hms(v) if var.type == "time" else v)
        gaps = [
            (parse_hms(b) - parse_hms(a)) if var.type == "time" else b - a
            for a, b in itertools.pairwise(ordered)
        ]
        step = min(gaps) if gaps else 1
        out.append(
            VariableInfo(
                name=name,
                kind="time" if var.type == "time" else "number",
                low=str(ordered[0]),
                high=str(ordered[-1]),
                step=str(step),
                unit=getattr(var, "unit", ""),
                initial=None if var.initial is None else str(var.initial),
            )
        )
    return Variables(variables=out)


def draft_features(model: ApplianceModel) -> Features:
    out = []
    for name, steps in model.features.items():
        infos = []
        for step in steps:
            presses = []
            for action in step.actions:
                effect, value = _effect_of(step, action)
                presses.append(Press(action=action, effect=effect, value=value))  # type: ignore[arg-type]
            sets = [Assignment(variable=k, value=str(v)) for k, v in step.set.items()]
            infos.append(StepInfo(variable=step.variable, presses=presses, sets=sets))
        out.append(FeatureInfo(name=name, steps=infos))
    return Features(features=out)
