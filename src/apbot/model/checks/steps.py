"""Checks of procedures and their effects: steps, optional steps, timeouts, anywhere-steps,
conditions, and effects that leave a variable's domain."""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Mapping
from typing import Any

from apbot.model.checks.common import unknown_name
from apbot.model.domain import (
    Domain,
    ValueProblem,
    build_domain,
    normalise,
)
from apbot.model.effects import (
    condition_values,
    default_effect,
    value_index,
)
from apbot.model.problems import PathPart, Problem
from apbot.model.schema import (
    Add,
    AnywhereStep,
    ApplianceModel,
    Conditional,
    Control,
    DiscreteVariable,
    GoTo,
    Step,
    time_step_seconds,
)
from apbot.model.values import preview


def _effects_of(step: Step | AnywhereStep, model: ApplianceModel) -> dict[str, Any]:
    return {a: default_effect(step, a, model) for a in step.actions if a in model.actions}


def check_steps(model: ApplianceModel, domains: Mapping[str, list[Domain]]) -> Iterator[Problem]:
    has_keypad = any(c.kind == "key" for c in model.controls)
    by_id: dict[str, Control] = {}
    for c in model.controls:
        by_id.setdefault(c.id, c)
    for name, action in model.actions.items():
        control = by_id.get(action.control_ids[0]) if action.control_ids else None
        if action.digit is not None:
            if not has_keypad or control is None or control.kind != "key":
                yield Problem(
                    ("actions", name, "digit"),
                    "a digit action must press a keypad key (a control of kind `key`)"
                    if has_keypad
                    else "digit actions on a model without a keypad: "
                    "declare the keypad keys as controls of kind `key`",
                    "keypad",
                )
            if action.skill != "press":
                yield Problem(("actions", name, "skill"), "keypad digits are pressed", "keypad")
        if (
            action.skill in ("turn_cw", "turn_ccw")
            and control is not None
            and control.kind not in ("dial", "knob")
        ):
            yield Problem(
                ("actions", name, "skill"),
                f"{action.skill} needs a dial or knob; {control.id!r} is a {control.kind}",
                "control",
            )
    for feature, steps in model.features.items():
        changes_something = False
        for s, step in enumerate(steps):
            path = ("features", feature, s)
            effects = _effects_of(step, model)
            value_effects = {a: e for a, e in effects.items() if e != "none"}
            if step.set or step.reset:
                changes_something = True
            if step.variable is None:
                if (isinstance(step.effect, dict) and value_effects) or (
                    step.effect not in (None, "none") and not isinstance(step.effect, dict)
                ):
                    yield Problem(
                        (*path, "effect"),
                        "this step has an effect but no `variable`"
                        " to apply it to; name the variable it adjusts",
                        "missing-variable",
                    )
                continue
            changes_something = True
            var = model.variables[step.variable]
            doms = domains.get(step.variable, [])
            if (
                step.effect is None
                and len(step.actions) > 1
                and not all(
                    model.actions[a].digit is not None for a in step.actions if a in model.actions
                )
            ):
                yield Problem(
                    (*path, "effect"),
                    f"{len(step.actions)} actions adjust "
                    f"{step.variable!r} but the step does not say how; give `effect` "
                    "as a map, e.g. {press_up: next, press_down: prev}",
                    "action-variable",
                )
            digit_actions = [a for a, e in effects.items() if e == "digit"]
            other_value = [a for a, e in value_effects.items() if e not in ("digit", "clear")]
            if digit_actions:
                if other_value:
                    yield Problem(
                        (*path, "effect"),
                        "keypad digits and other value changes "
                        f"({other_value}) share a step; the input buffer belongs to "
                        "one step, so give the others a step of their own",
                        "keypad-buffer",
                    )
                entry = getattr(var, "entry", None)
                if entry is None:
                    yield Problem(
                        ("variables", step.variable, "entry"),
                        f"keypad digits set {step.variable!r} in "
                        f"features.{feature}[{s}] but it declares no `entry` format "
                        "to read the typed digits",
                        "keypad-buffer",
                    )
                for a in digit_actions:
                    if model.actions[a].digit is None:
                        yield Problem(
                            (*path, "effect", a),
                            f"{a!r} types a digit but the action declares no `digit`",
                            "keypad",
                        )
            for key, effect in value_effects.items():
                at = (
                    (*path, "effect")
                    if not isinstance(step.effect, dict)
                    else (*path, "effect", key)
                )
                for when in _conditions_in(effect):
                    yield from condition_problems(model, (*at, "when"), when)
                message = _effect_problem(effect, var, doms)
                if message:
                    yield Problem(
                        (*path, "effect")
                        if not isinstance(step.effect, dict)
                        else (*path, "effect", key),
                        message,
                        "action-variable",
                    )
            for target, value in step.set.items():
                target_var = model.variables[target]
                if target == step.variable:
                    yield Problem(
                        (*path, "set", target),
                        "a step cannot both adjust and `set` the same variable",
                        "action-variable",
                    )
                try:
                    for dom in domains.get(target, []):
                        if _in_some(value, target_var, [dom]):
                            break
                    else:
                        normalise(target_var, value)
                except ValueProblem as exc:
                    yield Problem((*path, "set", target), str(exc), "action-variable")
            if step.variable in step.reset:
                yield Problem(
                    (*path, "reset"),
                    f"the step adjusts {step.variable!r} and also "
                    "resets it, which undoes every press; remove it from `reset`",
                    "action-variable",
                )
        if not changes_something:
            yield Problem(
                ("features", feature),
                "no step of this feature adjusts a variable "
                "or sets one; name the variable each step adjusts",
                "missing-variable",
            )


def check_procedure_options(model: ApplianceModel) -> Iterator[Problem]:
    """Optional steps need steps around them; timeouts need a wait long enough, and a wait
    needs a timeout it can let expire."""
    waits = {n: a.seconds or 0.0 for n, a in model.actions.items() if a.skill == "wait"}
    timeouts: list[float] = []
    for feature, steps in model.features.items():
        for s, step in enumerate(steps):
            path = ("features", feature, s)
            if step.optional and s == 0:
                yield Problem(
                    (*path, "optional"),
                    "the first step cannot be optional: it is how the feature starts; "
                    "make the step a feature of its own or drop `optional`",
                    "optional-step",
                )
            elif step.optional and s == len(steps) - 1:
                yield Problem(
                    (*path, "optional"),
                    "the last step cannot be optional: no step follows it to skip to; "
                    "drop `optional`",
                    "optional-step",
                )
            if step.timeout is not None:
                timeouts.append(step.timeout)
                if not any(seconds + 1e-9 >= step.timeout for seconds in waits.values()):
                    yield Problem(
                        (*path, "timeout"),
                        f"no wait action lasts {step.timeout:g} s, so nobody can let this "
                        "timeout expire; declare one, e.g. "
                        f"wait_{step.timeout:g}s: {{skill: wait, seconds: {step.timeout:g}}}",
                        "timeout",
                        severity="warning",
                    )
    for name, seconds in waits.items():
        if not any(seconds + 1e-9 >= t for t in timeouts):
            yield Problem(
                ("actions", name, "seconds"),
                f"waiting {seconds:g} s lets no step's `timeout` expire (the timeouts: "
                f"{sorted(timeouts) or 'none'}); give a step a timeout or remove the wait",
                "timeout",
                severity="warning",
            )
        used = [
            f"features.{f}[{s}]"
            for f, steps in model.features.items()
            for s, step in enumerate(steps)
            if name in step.actions
        ] + [f"anywhere[{i}]" for i, entry in enumerate(model.anywhere) if name in entry.actions]
        if used:
            yield Problem(
                ("actions", name),
                f"the wait {name!r} is listed in {used[0]}; a wait presses nothing, so it "
                "belongs to no step (it only lets timeouts expire)",
                "timeout",
            )


def check_anywhere(model: ApplianceModel, domains: Mapping[str, list[Domain]]) -> Iterator[Problem]:
    """Anywhere keys belong to no feature, change something (or leave), and their effects
    fit their variable; keypad digits stay in a feature's step."""
    in_features = {
        a: f"features.{f}[{s}]"
        for f, steps in model.features.items()
        for s, step in enumerate(steps)
        for a in step.actions
    }
    seen: dict[str, int] = {}
    for i, entry in enumerate(model.anywhere):
        path = ("anywhere", i)
        for a, action in enumerate(entry.actions):
            where = in_features.get(action)
            if where is not None:
                yield Problem(
                    (*path, "actions", a),
                    f"{action!r} is also in {where}; a key that acts from anywhere belongs "
                    "to no feature: remove it from one of them",
                    "anywhere",
                )
            if action in seen:
                yield Problem(
                    (*path, "actions", a),
                    f"{action!r} is already in anywhere[{seen[action]}]; list each key once",
                    "duplicate-sequence",
                )
            spec = model.actions.get(action)
            if spec is not None and spec.too_short == "enters":
                yield Problem(
                    (*path, "actions", a),
                    f"{action!r} acts from anywhere, so a hold released early has no "
                    "procedure to enter and is ignored; drop `too_short` from the action",
                    "anywhere",
                    severity="warning",
                )
            seen.setdefault(action, i)
        effects = _effects_of(entry, model)
        value_effects = {a: e for a, e in effects.items() if e != "none"}
        if entry.variable is None:
            if value_effects:
                yield Problem(
                    (*path, "effect"),
                    "this entry has an effect but no `variable` to apply it to",
                    "missing-variable",
                )
            if not (entry.set or entry.reset or entry.leave):
                yield Problem(
                    path,
                    "this entry changes nothing and does not `leave`: name the variable it "
                    "adjusts, give `set`/`reset`, or say `leave: true` (CANCEL)",
                    "missing-variable",
                )
            continue
        var = model.variables[entry.variable]
        if entry.effect is None and len(entry.actions) > 1:
            yield Problem(
                (*path, "effect"),
                f"{len(entry.actions)} actions adjust {entry.variable!r} but the entry does not "
                "say how; give `effect` as a map",
                "action-variable",
            )
        for key, effect in value_effects.items():
            epath = (*path, "effect", key) if isinstance(entry.effect, dict) else (*path, "effect")
            if effect in ("digit", "clear"):
                yield Problem(
                    epath,
                    f"{effect} works on a keypad buffer, which belongs to a feature's step; "
                    "put the keypad in a feature",
                    "keypad-buffer",
                )
                continue
            message = _effect_problem(effect, var, domains.get(entry.variable, []))
            if message:
                yield Problem(epath, message, "action-variable")
        for target, value in entry.set.items():
            if target == entry.variable:
                yield Problem(
                    (*path, "set", target),
                    "an entry cannot both adjust and `set` the same variable",
                    "action-variable",
                )
            if not _in_some(value, model.variables[target], domains.get(target, [])):
                try:
                    normalise(model.variables[target], value)
                except ValueProblem as exc:
                    yield Problem((*path, "set", target), str(exc), "action-variable")


def _conditions_in(effect: Any) -> list[dict[str, Any]]:
    """The ``when`` of a conditional effect and of the conditionals nested in it."""
    if not isinstance(effect, Conditional):
        return []
    return [effect.when, *_conditions_in(effect.then), *_conditions_in(effect.otherwise)]


def condition_problems(
    model: ApplianceModel, path: tuple[PathPart, ...], when: Mapping[str, Any]
) -> Iterator[Problem]:
    """A condition (of a guard or a conditional effect) reads known independent variables
    and names their values."""
    variables = list(model.variables)
    for name, wanted in when.items():
        var = model.variables.get(name)
        if var is None:
            yield Problem((*path, name), unknown_name("variable", name, variables), "reference")
            continue
        if var.depends_on is not None:
            yield Problem(
                (*path, name),
                "conditions read independent variables (power, a programme, a time)",
                "action-variable",
            )
            continue
        domain = build_domain(var)
        for value in condition_values(wanted):
            if value_index(domain, value) is None:
                yield Problem(
                    (*path, name),
                    f"{value!r} is not a value of {name!r} ({preview(domain.values)})",
                    "action-variable",
                )


def _in_some(value: Any, var: Any, doms: list[Domain]) -> bool:
    return any(value_index(d, value) is not None for d in doms)


def _effect_problem(effect: Any, var: Any, doms: list[Domain]) -> str | None:
    if isinstance(effect, Conditional):
        for branch in (effect.then, effect.otherwise):
            if branch in ("digit", "clear"):
                return f"a conditional effect changes the value; {branch} belongs to a keypad step"
            message = _effect_problem(branch, var, doms)
            if message:
                return message
        return None
    sizes = {len(d) for d in doms}
    if effect == "toggle" and sizes != {2}:
        return "toggle needs a variable with exactly two values; use next/prev"
    if effect == "digit" and isinstance(var, DiscreteVariable):
        return "keypad digits set numbers or times, not a discrete variable"
    if isinstance(effect, Add):
        if isinstance(var, DiscreteVariable):
            return "add applies to numbers and times, not to a discrete variable"
        if isinstance(effect.add, str) and var.type != "time":
            return f"add {effect.add!r}: a numeric variable adds a number"
        if isinstance(effect.add, str):
            try:
                time_step_seconds(effect.add)
            except ValueError:
                return (
                    f"add {effect.add!r}: give seconds (30, -30) or HH:MM:SS "
                    '("00:00:30", "-00:00:30")'
                )
    if isinstance(effect, GoTo) and not _in_some(effect.to, var, doms):
        values = list(itertools.islice((v for d in doms for v in d.values), 9))
        more = ", …" if len(values) > 8 else ""
        return f"go-to value {effect.to!r} is not a value of the variable ({values[:8]}{more})"
    return None
