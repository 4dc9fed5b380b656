"""Semantic checks of a schema-valid model: the paper's nine, and the ones a real model needs.

Each check returns :class:`Problem` objects with the path of the offending part and what to do
about it, so that an author (or an LLM being re-asked) can fix the model without guessing.

Check names (the paper's nine first):
    ``missing-variable``, ``empty-action``, ``unknown-action``, ``action-coverage``,
    ``variable-coverage``, ``duplicate-sequence``, ``keypad``, ``keypad-buffer``,
    ``action-variable``, ``goal`` (see :func:`check_goal`);
    then ``size`` (first: see :mod:`apbot.model.limits`), ``reference``, ``domain``,
    ``dependent``, ``guard``, ``display``, ``control``, ``cycle``,
    ``unreachable-value``, ``optional-step``, ``timeout``, ``anywhere``.
"""

from __future__ import annotations

import itertools
from collections import Counter
from collections.abc import Iterable, Iterator, Mapping
from typing import Any

from apbot.model.domain import (
    Domain,
    DomainError,
    ValueProblem,
    build_domain,
    domain_size,
    marked_unreachable,
    normalise,
)
from apbot.model.effects import (
    condition_values,
    constant_table,
    default_effect,
    effect_table,
    entry_digits,
    leaf_effects,
    value_index,
)
from apbot.model.limits import (
    MAX_MODEL_VALUES,
    MAX_PARTS,
    MAX_STEPS,
    MAX_VALUES,
    SIZE_LIMITS_DOC,
)
from apbot.model.problems import PathPart, Problem
from apbot.model.schema import (
    TEMPLATE_FIELD,
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
from apbot.model.values import closest_matches, preview

LIMITS = f"see {SIZE_LIMITS_DOC}"


class _Names(list[str]):
    """Names in order (for "did you mean" hints) with a set for O(1) ``in``."""

    def __init__(self, names: Iterable[str]) -> None:
        super().__init__(names)
        self.members = frozenset(self)

    def __contains__(self, name: object) -> bool:
        return name in self.members


def _unknown(kind: str, name: str, options: list[str]) -> str:
    close = closest_matches(name, options, limit=1)
    hint = f"did you mean {close[0]!r}?" if close else f"declare it under `{kind}s`"
    return f"unknown {kind} {name!r}; {hint}"


def check_model(model: ApplianceModel) -> list[Problem]:
    """Every problem of the model; errors make it unusable, warnings are advice."""
    too_large = list(_sizes(model))
    if too_large:
        return too_large  # every later check is linear in the model; past a limit, stop here
    problems = list(_references(model))
    domains, domain_problems = _domains(model)
    problems += domain_problems
    if any(p.severity == "error" for p in problems):
        return problems  # later checks need resolvable names and buildable domains
    problems += _steps(model, domains)
    problems += _procedure_options(model)
    problems += _anywhere(model, domains)
    problems += _coverage(model)
    problems += _duplicates(model)
    problems += _guards(model)
    problems += _controls(model)
    problems += _cycles(model)
    problems += _unreachable_marks(model)
    if not any(p.severity == "error" for p in problems):
        problems += _reachability(model)
    return problems


# --- sizes --------------------------------------------------------------------------------------


def _sizes(model: ApplianceModel) -> Iterator[Problem]:
    """The model's size against :mod:`apbot.model.limits`, counted without building anything."""
    parts = {
        "controls": len(model.controls),
        "actions": len(model.actions),
        "variables": len(model.variables),
        "features": len(model.features),
        "guards": len(model.guards),
    }
    for key, count in parts.items():
        if count > MAX_PARTS:
            yield Problem(
                (key,), f"{count:,} {key}; a model has at most {MAX_PARTS:,} ({LIMITS})", "size"
            )
    steps = sum(len(s) for s in model.features.values())
    if steps > MAX_STEPS:
        yield Problem(
            ("features",),
            f"{steps:,} steps in all; a model has at most {MAX_STEPS:,} ({LIMITS})",
            "size",
        )
    total = 0
    for name, var in model.variables.items():
        cases: list[tuple[str | None, Any]] = (
            list((var.cases or {}).items()) if var.depends_on is not None else [(None, None)]
        )
        for case_key, case in cases:
            size = domain_size(var, case)
            total += size
            if size > MAX_VALUES:
                path: tuple[PathPart, ...] = ("variables", name)
                if case_key is not None:
                    path = (*path, "cases", case_key)
                yield Problem(
                    path,
                    f"{size:,} values; a domain has at most {MAX_VALUES:,} ({LIMITS})",
                    "size",
                )
    if total > MAX_MODEL_VALUES:
        yield Problem(
            ("variables",),
            f"the domains hold {total:,} values in all; a model has at most "
            f"{MAX_MODEL_VALUES:,} ({LIMITS})",
            "size",
        )


# --- references -----------------------------------------------------------------------------


def _references(model: ApplianceModel) -> Iterator[Problem]:
    controls = _Names(c.id for c in model.controls)
    variables = _Names(model.variables)
    actions = _Names(model.actions)
    seen: set[str] = set()
    for i, control in enumerate(model.controls):
        if control.id in seen:
            yield Problem(
                ("controls", i, "id"), f"control {control.id!r} is declared twice", "reference"
            )
        seen.add(control.id)
    for name, spec in model.actions.items():
        for cid in spec.control_ids:
            if cid not in controls:
                key = "control" if spec.control else "controls"
                yield Problem(
                    ("actions", name, key), _unknown("control", cid, controls), "reference"
                )
    for name, var in model.variables.items():
        if var.depends_on is not None and var.depends_on not in variables:
            yield Problem(
                ("variables", name, "depends_on"),
                _unknown("variable", var.depends_on, variables),
                "reference",
            )
    for feature, steps in model.features.items():
        if not steps:
            yield Problem(
                ("features", feature), "a feature needs at least one step", "empty-action"
            )
        for s, step in enumerate(steps):
            path = ("features", feature, s)
            if not step.actions:
                yield Problem(
                    (*path, "actions"), "a step needs at least one action", "empty-action"
                )
            for a, action in enumerate(step.actions):
                if action not in actions:
                    yield Problem(
                        (*path, "actions", a), _unknown("action", action, actions), "unknown-action"
                    )
            if step.variable is not None and step.variable not in variables:
                yield Problem(
                    (*path, "variable"), _unknown("variable", step.variable, variables), "reference"
                )
            if isinstance(step.effect, dict):
                step_actions = set(step.actions)
                for action in step.effect:
                    if action not in step_actions:
                        yield Problem(
                            (*path, "effect", action),
                            f"{action!r} has an effect here but is not one of the "
                            f"step's actions {preview(step.actions)}",
                            "action-variable",
                        )
            for target in [*step.set, *step.reset]:
                if target not in variables:
                    key = "set" if target in step.set else "reset"
                    yield Problem(
                        (*path, key), _unknown("variable", target, variables), "reference"
                    )
    for i, entry in enumerate(model.anywhere):
        apath: tuple[PathPart, ...] = ("anywhere", i)
        if not entry.actions:
            yield Problem((*apath, "actions"), "an anywhere entry needs an action", "empty-action")
        for a, action in enumerate(entry.actions):
            if action not in actions:
                yield Problem(
                    (*apath, "actions", a), _unknown("action", action, actions), "unknown-action"
                )
        if entry.variable is not None and entry.variable not in variables:
            yield Problem(
                (*apath, "variable"), _unknown("variable", entry.variable, variables), "reference"
            )
        for action in entry.effect if isinstance(entry.effect, dict) else ():
            if action not in entry.actions:
                yield Problem(
                    (*apath, "effect", action),
                    f"{action!r} has an effect here but is not one of the entry's actions "
                    f"{preview(entry.actions)}",
                    "action-variable",
                )
        for target in [*entry.set, *entry.reset]:
            if target not in variables:
                key = "set" if target in entry.set else "reset"
                yield Problem((*apath, key), _unknown("variable", target, variables), "reference")
    for g, guard in enumerate(model.guards):
        for name in guard.when:
            if name not in variables:
                yield Problem(
                    ("guards", g, "when", name), _unknown("variable", name, variables), "reference"
                )
        for a, action in enumerate(guard.only):
            if action not in actions:
                yield Problem(
                    ("guards", g, "only", a), _unknown("action", action, actions), "unknown-action"
                )
    for name in model.display.indicators:
        if name not in variables:
            yield Problem(
                ("display", "indicators"), _unknown("variable", name, variables), "reference"
            )
    for field in TEMPLATE_FIELD.findall(model.display.idle):
        if field not in variables:
            yield Problem(("display", "idle"), _unknown("variable", field, variables), "display")
    for name, var in model.variables.items():
        shows = var.show.values() if isinstance(var.show, dict) else [var.show or ""]
        for text in shows:
            for field in TEMPLATE_FIELD.findall(text):
                if field not in (*variables, "value", "label"):
                    yield Problem(
                        ("variables", name, "show"),
                        f"template field {{{field}}} is not a variable, {{value}} or {{label}}",
                        "display",
                    )


# --- domains ----------------------------------------------------------------------------------


def _domains(model: ApplianceModel) -> tuple[dict[str, list[Domain]], list[Problem]]:
    """Every domain of every variable (one, or one per case), and the problems building them."""
    domains: dict[str, list[Domain]] = {}
    problems: list[Problem] = []
    for name, var in model.variables.items():
        path = ("variables", name)
        if var.remember and var.depends_on is None:
            problems.append(
                Problem(
                    (*path, "remember"),
                    "`remember` keeps a value per programme; it needs `depends_on` (the "
                    "programme or zone selecting the case)",
                    "dependent",
                )
            )
        if var.depends_on is None:
            try:
                domains[name] = [build_domain(var)]
            except DomainError as exc:
                problems.append(Problem(path, str(exc), "domain"))
            continue
        parent = model.variables.get(var.depends_on)
        if parent is None:
            continue
        if not isinstance(parent, DiscreteVariable) or parent.depends_on is not None:
            problems.append(
                Problem(
                    (*path, "depends_on"),
                    f"{var.depends_on!r} must be an independent discrete variable "
                    "(a programme or menu) to select cases",
                    "dependent",
                )
            )
            continue
        parent_values = parent.values or []
        parent_set = set(parent_values)
        domains[name] = []
        for key, case in (var.cases or {}).items():
            if key not in parent_set:
                problems.append(
                    Problem(
                        (*path, "cases", key),
                        f"{key!r} is not a value of {var.depends_on!r} "
                        f"({preview(parent_values)})" + _close(key, parent_values),
                        "dependent",
                    )
                )
                continue
            try:
                domains[name].append(build_domain(var, case))
            except DomainError as exc:
                problems.append(Problem((*path, "cases", key), str(exc), "domain"))
        if not var.cases or not any(k in parent_set for k in var.cases):
            problems.append(
                Problem(
                    (*path, "cases"), f"no case matches a value of {var.depends_on!r}", "dependent"
                )
            )
    return domains, problems


def _close(text: str, options: list[str]) -> str:
    close = closest_matches(text, options, limit=1)
    return f"; did you mean {close[0]!r}?" if close else ""


# --- steps and effects ---------------------------------------------------------------------


def _effects_of(step: Step | AnywhereStep, model: ApplianceModel) -> dict[str, Any]:
    return {a: default_effect(step, a, model) for a in step.actions if a in model.actions}


def _steps(model: ApplianceModel, domains: Mapping[str, list[Domain]]) -> Iterator[Problem]:
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
                    yield from _condition_problems(model, (*at, "when"), when)
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


def _procedure_options(model: ApplianceModel) -> Iterator[Problem]:
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


def _anywhere(model: ApplianceModel, domains: Mapping[str, list[Domain]]) -> Iterator[Problem]:
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


def _condition_problems(
    model: ApplianceModel, path: tuple[PathPart, ...], when: Mapping[str, Any]
) -> Iterator[Problem]:
    """A condition (of a guard or a conditional effect) reads known independent variables
    and names their values."""
    variables = list(model.variables)
    for name, wanted in when.items():
        var = model.variables.get(name)
        if var is None:
            yield Problem((*path, name), _unknown("variable", name, variables), "reference")
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


# --- coverage, duplicates ----------------------------------------------------------------------


def _coverage(model: ApplianceModel) -> Iterator[Problem]:
    used_actions = {a for steps in model.features.values() for s in steps for a in s.actions}
    used_actions |= {a for entry in model.anywhere for a in entry.actions}
    used_actions |= {n for n, a in model.actions.items() if a.skill == "wait"}  # see timeouts
    for name in model.actions:
        if name not in used_actions:
            yield Problem(
                ("actions", name),
                f"action {name!r} appears in no feature; add it "
                "to the step it belongs to or remove it",
                "action-coverage",
            )
    changed = {s.variable for steps in model.features.values() for s in steps if s.variable}
    changed |= {v for steps in model.features.values() for s in steps for v in [*s.set, *s.reset]}
    changed |= {v for e in model.anywhere for v in [e.variable, *e.set, *e.reset] if v}
    changed |= {v for cycle in model.cycles for v in [*cycle.set, *cycle.reset]}
    for name in model.variables:
        if name not in changed:
            yield Problem(
                ("variables", name),
                f"no feature changes {name!r}; name it as the "
                "`variable` of the step that adjusts it",
                "variable-coverage",
            )


def _duplicates(model: ApplianceModel) -> Iterator[Problem]:
    signatures: dict[str, str] = {}
    for feature, steps in model.features.items():
        signature = repr([s.model_dump() for s in steps])
        if signature in signatures:
            yield Problem(
                ("features", feature),
                f"same steps as feature {signatures[signature]!r}; keep one",
                "duplicate-sequence",
            )
        signatures.setdefault(signature, feature)
        for s, step in enumerate(steps):
            repeated = sorted(a for a, n in Counter(step.actions).items() if n > 1)
            if repeated:
                yield Problem(
                    ("features", feature, s, "actions"),
                    f"{repeated[0]!r} is listed twice in one step",
                    "duplicate-sequence",
                )
        for s, (a, b) in enumerate(itertools.pairwise(steps)):
            if a.variable and a.variable == b.variable and set(a.actions) & set(b.actions):
                yield Problem(
                    ("features", feature, s + 1),
                    f"steps {s} and {s + 1} adjust {a.variable!r} with the same "
                    "actions; merge them into one step",
                    "duplicate-sequence",
                    severity="warning",
                )
    claimed: dict[str, str] = {}
    for feature, steps in model.features.items():
        if not steps:
            continue
        first = [a for a in steps[0].actions if a in model.actions]
        if first and all(a in claimed for a in first):
            owners = sorted({claimed[a] for a in first})
            yield Problem(
                ("features", feature, 0, "actions"),
                f"feature {feature!r} can never start: every action of its first step "
                f"already starts {owners}; give it a distinct first action or merge "
                "the features",
                "duplicate-sequence",
            )
        for action in first:
            claimed.setdefault(action, feature)


# --- guards, controls ----------------------------------------------------------------------------


def _guards(model: ApplianceModel) -> Iterator[Problem]:
    for g, guard in enumerate(model.guards):
        for name, wanted in guard.when.items():
            var = model.variables[name]
            if var.depends_on is not None:
                yield Problem(
                    ("guards", g, "when", name),
                    "guard conditions use independent variables (power, child lock, running)",
                    "guard",
                )
                continue
            domain = build_domain(var)
            for value in condition_values(wanted):
                if value_index(domain, value) is None:
                    yield Problem(
                        ("guards", g, "when", name),
                        f"{value!r} is not a value of {name!r} ({preview(domain.values)})",
                        "guard",
                    )
        allowed = set(guard.only)
        everywhere: list[Step | AnywhereStep] = [s for f in model.features.values() for s in f]
        releasing = [
            s
            for s in [*everywhere, *model.anywhere]
            if any(a in allowed for a in s.actions)
            and (s.variable in guard.when or any(v in guard.when for v in [*s.set, *s.reset]))
        ]
        if not releasing:
            yield Problem(
                ("guards", g, "only"),
                "no allowed action changes "
                f"{sorted(guard.when)}, so once the guard holds nothing can lift it; "
                "allow the action that releases it",
                "guard",
            )


CYCLE_UNITS = {"s": 1, "sec": 1, "min": 60, "h": 3600}  # a numeric cycle length's unit


def _cycles(model: ApplianceModel) -> Iterator[Problem]:
    """A cycle's conditions, its length variable and its end's side effects make sense."""
    variables = list(model.variables)
    for c, cycle in enumerate(model.cycles):
        path: tuple[PathPart, ...] = ("cycles", c)
        yield from _condition_problems(model, (*path, "when"), cycle.when)
        lasts = model.variables.get(cycle.lasts)
        if lasts is None:
            yield Problem(
                (*path, "lasts"), _unknown("variable", cycle.lasts, variables), "reference"
            )
        elif lasts.depends_on is not None or not (
            lasts.type == "time" or (lasts.type == "numeric" and lasts.unit in CYCLE_UNITS)
        ):
            yield Problem(
                (*path, "lasts"),
                f"{cycle.lasts!r} cannot say how long the cycle lasts: give an independent "
                "time variable, or a numeric one in s, min or h",
                "cycle",
            )
        for target, value in cycle.set.items():
            target_var = model.variables.get(target)
            if target_var is None:
                yield Problem(
                    (*path, "set", target), _unknown("variable", target, variables), "reference"
                )
                continue
            try:
                normalise(target_var, value)
            except ValueProblem as exc:
                yield Problem((*path, "set", target), str(exc), "cycle")
        for target in cycle.reset:
            if target not in model.variables:
                yield Problem(
                    (*path, "reset"), _unknown("variable", target, variables), "reference"
                )
        if not cycle.set and not cycle.reset:
            yield Problem(path, "a cycle's end changes nothing; give `set` or `reset`", "cycle")


def _controls(model: ApplianceModel) -> Iterator[Problem]:
    used = {cid for action in model.actions.values() for cid in action.control_ids}
    for i, control in enumerate(model.controls):
        if control.box is not None:
            x0, y0, x1, y1 = control.box
            if x1 <= x0 or y1 <= y0:
                yield Problem(
                    ("controls", i, "box"),
                    f"box {list(control.box)} is empty; write "
                    "[left, top, right, bottom] with right > left and bottom > top",
                    "control",
                )
        if control.id not in used:
            yield Problem(
                ("controls", i),
                f"control {control.id!r} is used by no action",
                "control",
                severity="warning",
            )


# --- reachability ----------------------------------------------------------------------------


def _unreachable_marks(model: ApplianceModel) -> Iterator[Problem]:
    """Each value a variable declares ``unreachable`` is one of its values, and not the
    initial value (of any programme) — that one the appliance starts in."""
    for name, var in model.variables.items():
        if not var.unreachable:
            continue
        defaults = {domain.values[domain.initial] for _, domain in _case_domains(model, name)}
        for i, raw in enumerate(var.unreachable):
            path = ("variables", name, "unreachable", i)
            try:
                value = normalise(var, raw)
            except ValueProblem as exc:
                yield Problem(path, f"{raw!r}: {exc}", "unreachable-value")
                continue
            if value in defaults:
                yield Problem(
                    path,
                    f"{value!r} is {name!r}'s initial value (or a programme's default), so "
                    "the appliance reaches it; remove it from `unreachable`",
                    "unreachable-value",
                )


def _reachability(model: ApplianceModel) -> Iterator[Problem]:
    """Values no sequence of effects can reach from the initial value (or a case default),
    unless declared ``unreachable``; and declared ones that some effect reaches after all."""
    for name, var in model.variables.items():
        marked = marked_unreachable(var)
        reached_marks: set[Any] = set()
        for case, domain in _case_domains(model, name):
            reached = reachable_indices(model, name, domain)
            reached_marks.update(v for i, v in enumerate(domain.values) if i in reached)
            missing = [
                domain.values[i]
                for i in range(len(domain))
                if i not in reached and domain.values[i] not in marked
            ]
            if missing:
                where: tuple[str, ...] = (
                    ("variables", name) if case is None else ("variables", name, "cases", case)
                )
                shown = ", ".join(str(m) for m in missing[:6])
                more = f" and {len(missing) - 6} more" if len(missing) > 6 else ""
                yield Problem(
                    where,
                    f"no action can reach {shown}{more}; fix the ranges or the "
                    "effects that adjust it, or declare values only the appliance sets "
                    "under `unreachable`",
                    "unreachable-value",
                )
        for value in sorted(marked & reached_marks, key=str):
            yield Problem(
                ("variables", name, "unreachable"),
                f"{value!r} is declared unreachable but an action of the model reaches it; "
                "remove it from `unreachable`",
                "unreachable-value",
                severity="warning",
            )


def _case_domains(model: ApplianceModel, name: str) -> list[tuple[str | None, Domain]]:
    """A variable's domains: its own (case None), or one per programme value with a case."""
    var = model.variables[name]
    if var.depends_on is None:
        return [(None, build_domain(var))]
    parent = model.variables[var.depends_on]
    cases = var.cases or {}
    return [
        (value, build_domain(var, cases[value]))
        for value in build_domain(parent).values
        if value in cases
    ]


def _tables_of(effect: Any, domain: Domain, var: Any) -> list[tuple[int, ...]]:
    """The value tables of one plain effect on one domain (none for digits and ``none``)."""
    if effect == "clear":
        return [constant_table(domain, domain.initial)]
    if effect in ("digit", "none"):
        return []
    table = effect_table(effect, domain, var)
    return [] if table is None else [table]


def reachable_indices(model: ApplianceModel, name: str, domain: Domain) -> set[int]:
    """Indices of one of ``name``'s domains reachable from its initial value through any
    effect or side effect of the model (the effect semantics of :mod:`apbot.model.effects`)."""
    var = model.variables[name]
    tables: list[tuple[int, ...]] = []
    typed = False
    every: list[Step | AnywhereStep] = [s for steps in model.features.values() for s in steps]
    for step in [*every, *model.anywhere]:
        if step.variable == name:
            for action in step.actions:
                for effect in leaf_effects(default_effect(step, action, model)):
                    tables += _tables_of(effect, domain, var)
                effect = default_effect(step, action, model)
                if effect == "digit":
                    typed = typed or getattr(var, "entry", None) is not None
        if name in step.set:
            table = effect_table(GoTo(to=step.set[name]), domain, var)
            if table is not None:
                tables.append(table)
        if name in step.reset:
            tables.append(constant_table(domain, domain.initial))
    typeable: set[int] = set()
    entry = getattr(var, "entry", None)
    if typed and entry is not None:  # once, not once per digit key
        assert domain.magnitudes is not None
        typeable = {
            i for i, m in enumerate(domain.magnitudes) if entry_digits(m, entry) is not None
        }
    reached = {domain.initial} | typeable
    frontier = list(reached)
    while frontier:
        index = frontier.pop()
        for table in tables:
            nxt = table[index]
            if nxt not in reached:
                reached.add(nxt)
                frontier.append(nxt)
    return reached


# --- goals ---------------------------------------------------------------------------------------


def check_goal(model: ApplianceModel, goal: Mapping[str, Any]) -> list[Problem]:
    """Goal validity (the paper's ninth check): known variables, values in their domains,
    and a programme-dependent setting valid for the goal's programme when one is given."""
    problems = []
    variables = list(model.variables)
    for name, raw in goal.items():
        path = ("goal", name)
        if name not in model.variables:
            problems.append(Problem(path, _unknown("variable", name, variables), "goal"))
            continue
        var = model.variables[name]
        try:
            value = normalise(var, raw)
        except ValueProblem as exc:
            problems.append(Problem(path, str(exc), "goal"))
            continue
        if var.depends_on is not None and var.depends_on in goal:
            parent = model.variables[var.depends_on]
            try:
                parent_value = normalise(parent, goal[var.depends_on])
            except ValueProblem:
                continue
            case = (var.cases or {}).get(parent_value)
            if case is None:
                problems.append(
                    Problem(
                        path,
                        f"{name!r} does not exist when {var.depends_on} is {parent_value!r}",
                        "goal",
                    )
                )
            else:
                try:
                    normalise(var, value, build_domain(var, case))
                except ValueProblem as exc:
                    problems.append(
                        Problem(path, f"{exc} when {var.depends_on} is {parent_value!r}", "goal")
                    )
    return problems
