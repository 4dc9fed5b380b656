"""Compiling a validated model into the lookup tables :class:`~apbot.sim.compiled.CompiledModel`
steps with: domains per programme, each step's effect tables, the feature pointer's moves, guards
and cycles.

Kept apart from the step semantics (:mod:`apbot.sim.compiled`) because building runs once per
model and reads the pydantic model, while stepping runs millions of times and reads only the
tables. Each function takes the model being compiled, whose earlier tables it reads.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from apbot.model.domain import build_domain
from apbot.model.effects import condition_indices, constant_table, default_effect, effect_table
from apbot.model.schema import Conditional, GoTo
from apbot.model.validate import CYCLE_UNITS
from apbot.sim.parts import (
    CLEAR,
    COND,
    DIGIT,
    NONE,
    TABLE,
    CycleInfo,
    GuardInfo,
    StepInfo,
    VarInfo,
)

if TYPE_CHECKING:
    from apbot.sim.compiled import CompiledModel


def compile_variable(cm: CompiledModel, name: str) -> VarInfo:
    spec = cm.model.variables[name]
    if spec.depends_on is None:
        return VarInfo(name, spec, (build_domain(spec),), -1)
    parent_index = cm.var_index[spec.depends_on]
    parent = build_domain(cm.model.variables[spec.depends_on])
    cases = spec.cases or {}
    domains = tuple(
        build_domain(spec, cases[value]) if value in cases else None for value in parent.values
    )
    return VarInfo(name, spec, domains, parent_index)


def _effect(cm: CompiledModel, effect: Any, var: VarInfo | None, action: int) -> tuple[Any, ...]:
    if var is None or effect in (None, "none"):
        return (NONE,)
    if isinstance(effect, Conditional):  # (COND, conditions, then, otherwise)
        return (
            COND,
            _conditions(cm, effect.when),
            _effect(cm, effect.then, var, action),
            _effect(cm, effect.otherwise, var, action),
        )
    if effect == "digit":
        return (DIGIT, cm.model.actions[cm.action_names[action]].digit)
    if effect == "clear":
        reset = tuple(None if d is None else constant_table(d, d.initial) for d in var.domains)
        return (CLEAR, reset)
    tables = tuple(None if d is None else effect_table(effect, d, var.spec) for d in var.domains)
    assigns = effect == "reset" or isinstance(effect, GoTo)  # choosing, not stepping
    return (TABLE, tables, assigns, effect == "reset")


def _step_parts(
    cm: CompiledModel, step: Any
) -> tuple[
    list[int],
    dict[int, tuple[Any, ...]],
    tuple[tuple[int, tuple[tuple[int, ...] | None, ...]], ...],
]:
    """A step's action ids, their compiled effects and its side effects."""
    var = cm.vars[cm.var_index[step.variable]] if step.variable else None
    action_ids = [cm.action_index[a] for a in step.actions]
    effects = {
        a: _effect(cm, default_effect(step, cm.action_names[a], cm.model), var, a)
        for a in action_ids
    }
    return action_ids, effects, _side_tables(cm, step.set, step.reset)


def compile_steps(cm: CompiledModel) -> tuple[StepInfo, ...]:
    steps: list[StepInfo] = []
    for feature, feature_steps in cm.model.features.items():
        base = len(steps)
        for index, step in enumerate(feature_steps):
            action_ids, effects, side = _step_parts(cm, step)
            next_step = base + index + 1 if index + 1 < len(feature_steps) else -1
            entry = (
                getattr(cm.model.variables[step.variable], "entry", None) if step.variable else None
            )
            steps.append(
                StepInfo(
                    feature,
                    index,
                    cm.var_index[step.variable] if step.variable else -1,
                    frozenset(action_ids),
                    effects,
                    side,
                    next_step,
                    step.on_entry == "show",
                    optional=step.optional,
                    timeout=step.timeout,
                    blank_clears=entry is not None and entry.other_keys == "clear",
                    forgets=frozenset(cm.var_index[t] for t in step.reset),
                )
            )
    return tuple(steps)


def compile_anywhere(cm: CompiledModel) -> tuple[StepInfo, ...]:
    """The ``anywhere`` entries, as steps of no feature (index -1, no next step)."""
    compiled = []
    for step in cm.model.anywhere:
        action_ids, effects, side = _step_parts(cm, step)
        compiled.append(
            StepInfo(
                "",
                -1,
                cm.var_index[step.variable] if step.variable else -1,
                frozenset(action_ids),
                effects,
                side,
                -1,
                leave=step.leave,
                forgets=frozenset(cm.var_index[t] for t in step.reset),
            )
        )
    return tuple(compiled)


def _side_tables(
    cm: CompiledModel, assigned: dict[str, Any], reset: list[str]
) -> tuple[tuple[int, tuple[tuple[int, ...] | None, ...]], ...]:
    """(variable, per-case tables) for ``set`` and ``reset`` side effects, in that order."""
    side = []
    for target, value in assigned.items():
        info = cm.vars[cm.var_index[target]]
        side.append(
            (
                cm.var_index[target],
                tuple(
                    None if d is None else effect_table(GoTo(to=value), d, info.spec)
                    for d in info.domains
                ),
            )
        )
    for target in reset:
        info = cm.vars[cm.var_index[target]]
        side.append(
            (
                cm.var_index[target],
                tuple(None if d is None else constant_table(d, d.initial) for d in info.domains),
            )
        )
    return tuple(side)


def compile_cycles(cm: CompiledModel) -> tuple[CycleInfo, ...]:
    cycles = []
    for cycle in cm.model.cycles:
        spec = cm.model.variables[cycle.lasts]
        scale = 1.0 if spec.type == "time" else CYCLE_UNITS[getattr(spec, "unit", "s")]
        cycles.append(
            CycleInfo(
                cycle.name,
                _conditions(cm, cycle.when),
                cm.var_index[cycle.lasts],
                float(scale),
                _side_tables(cm, cycle.set, cycle.reset),
                frozenset(cm.var_index[t] for t in cycle.reset),
            )
        )
    return tuple(cycles)


def first_steps(cm: CompiledModel) -> dict[int, int]:
    """Action -> the step id of the first feature (in order) whose first step has it."""
    first: dict[int, int] = {}
    for sid, step in enumerate(cm.steps):
        if step.index == 0:
            for action in sorted(step.actions):
                first.setdefault(action, sid)
    return first


def compile_targets(cm: CompiledModel) -> tuple[tuple[int, ...], ...]:
    """``targets[pointer + 1][action]``: the step an action moves the pointer to, or -1."""
    rows = []
    for pointer in range(-1, len(cm.steps)):
        row = []
        for action in range(len(cm.action_names)):
            target = cm.first_steps.get(action, -1)
            if pointer >= 0:
                step = cm.steps[pointer]
                if action in step.actions:
                    target = pointer
                else:
                    later = step.next_step  # the next step, or past optional ones
                    while later >= 0:
                        if action in cm.steps[later].actions:
                            target = later
                            break
                        later = cm.steps[later].next_step if cm.steps[later].optional else -1
            if action in cm.anywhere or action in cm.waits:
                target = -1  # these never move the pointer through this table
            row.append(target)
        rows.append(tuple(row))
    return tuple(rows)


def _conditions(cm: CompiledModel, when: dict[str, Any]) -> tuple[tuple[int, frozenset[int]], ...]:
    """(variable, accepted value indices) per condition of a guard or conditional effect
    (conditions read independent variables, so their one domain)."""
    conditions = []
    for name, wanted in when.items():
        domain = cm.vars[cm.var_index[name]].domains[0]
        assert domain is not None
        conditions.append((cm.var_index[name], condition_indices(domain, wanted)))
    return tuple(conditions)


def compile_guards(cm: CompiledModel) -> tuple[GuardInfo, ...]:
    guards = []
    for guard in cm.model.guards:
        allowed = frozenset(cm.action_index[a] for a in guard.only)
        guards.append(
            GuardInfo(_conditions(cm, guard.when), allowed, guard.display, guard.name, guard.hide)
        )
    return tuple(guards)
