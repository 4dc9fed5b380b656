"""Random small appliance models and goals, for checking the planner against brute force.

The models use every part of the format a planner has to get right: discrete, numeric and time
variables, piecewise ranges, wrap and clamp, keypads (numbers and times, a CLEAR key),
programme-dependent settings (a programme chosen by a cycling key, a dial or go-to keys, a
programme without a case), entry steps, confirm steps, ``on_entry: show``, go-to, add, reset,
toggle and ``none`` effects, holds and two-control holds (some entering when released early),
dial turns, side effects (``set``, ``reset``) on any step, optional steps, keys that act from
anywhere (some leaving the procedure), step timeouts with a wait, keypads whose other keys
clear the typing, and guards — power off, a child lock, "only these keys while running",
a mode that allows only some keys, a number that must be set first. They stay small enough
(mostly a few thousand states) for breadth-first search over the whole simulator.
Generation is driven by a ``random.Random`` so a failing case is reproducible from its seed;
:func:`format_parts` says which parts a model uses, so tests can check the generator's reach.

The drawing lives in :mod:`apbot.testing.builder` (with :mod:`~apbot.testing.variables` and
:mod:`~apbot.testing.extras`); :mod:`apbot.testing.parts` names the parts a model uses.
"""

from __future__ import annotations

import random
from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import ApplianceModel
from apbot.sim.checks import guard_problems
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import random_walk
from apbot.testing.builder import Builder
from apbot.testing.parts import FORMAT_PARTS, format_parts

__all__ = ["FORMAT_PARTS", "format_parts", "random_goal", "random_model", "state_bound"]


def random_model(rng: random.Random, max_states: int = 30_000) -> ApplianceModel:
    """A schema-valid model with all references resolved (semantic checks may still warn),
    with at most ``max_states`` states (:func:`state_bound`) and no guard that holds for good
    (:func:`apbot.sim.checks.guard_problems`): other draws are discarded and drawn again from
    the same ``rng``, so such cases are not generated at all."""
    for _ in range(1_000):
        model = Builder(rng).build()
        if state_bound(model) <= max_states and not guard_problems(model):
            return model  # (guards that together lock the appliance for good are drawn again)
    raise ValueError(f"no model with at most {max_states} states in 1,000 draws; allow more")


def state_bound(model: ApplianceModel) -> int:
    """An upper bound on the number of states: every combination of values (a dependent
    setting counts its largest case, plus "absent"; a remembered one every combination of
    its cases' values), times every pointer position, where a
    keypad step counts once per buffer it can hold."""
    total = 1
    for var in model.variables.values():
        if var.depends_on is None:
            total *= len(build_domain(var))
        else:
            parent = build_domain(model.variables[var.depends_on]).values
            cases = var.cases or {}
            if var.remember:  # a value kept for every programme (the current one shown)
                for case in cases.values():
                    total *= len(build_domain(var, case))
                continue
            total *= max(len(build_domain(var, c)) for c in cases.values()) + (
                len(cases) < len(parent)
            )
    positions = 1  # no feature entered yet
    for steps in model.features.values():
        for step in steps:
            entry = None
            if step.variable is not None:
                entry = getattr(model.variables[step.variable], "entry", None)
            positions += 1 if entry is None else sum(10**k for k in range(entry.digits() + 1))
    return total * positions


def random_goal(rng: random.Random, model: ApplianceModel) -> dict[str, Any]:
    """A goal over one to three variables: values drawn from their domains, or (half the
    time) read off a state reached by a random walk, so that it is usually reachable.

    With programme-dependent settings, a quarter of the goals ask for a setting's value that
    is some programme's default without naming the programme, so that changing programme is
    a candidate route (the family of ``planner_not_optimal`` in issue 8)."""
    dependents = [n for n, v in model.variables.items() if v.depends_on is not None]
    if dependents and rng.random() < 0.25:
        return _default_elsewhere_goal(rng, model, rng.choice(dependents))
    names = rng.sample(list(model.variables), rng.randint(1, min(3, len(model.variables))))
    if rng.random() < 0.5:
        compiled = compiled_model(model)
        state = random_walk(compiled, rng, rng.randint(3, 30))
        walked = {n: compiled.value(state, n) for n in names}
        if all(v is not None for v in walked.values()):
            return walked
    names.sort(key=lambda n: model.variables[n].depends_on is not None)  # parents first
    goal: dict[str, Any] = {}
    programme: dict[str, Any] = {}  # the programme each dependent value was drawn for
    for name in names:
        var = model.variables[name]
        if var.depends_on is not None:
            parent = var.depends_on
            parent_domain = build_domain(model.variables[parent])
            options = [v for v in parent_domain.values if v in (var.cases or {})]
            chosen = goal.get(parent) or programme.get(parent) or rng.choice(options)
            programme[parent] = chosen  # a second setting of it must exist there too
            if chosen not in (var.cases or {}):
                continue
            if parent in goal or rng.random() < 0.5:  # else: any programme offering it will do
                goal.setdefault(parent, chosen)
            domain = build_domain(var, (var.cases or {})[chosen])
        else:
            domain = build_domain(var)
        goal[name] = domain.values[rng.randrange(len(domain))]
    return goal


def _default_elsewhere_goal(rng: random.Random, model: ApplianceModel, name: str) -> dict[str, Any]:
    """A dependent setting at one programme's default (the programme not named), and
    sometimes one more variable that is neither."""
    var = model.variables[name]
    case = rng.choice(list((var.cases or {}).values()))
    domain = build_domain(var, case)
    goal: dict[str, Any] = {name: domain.values[domain.initial]}
    others = [n for n in model.variables if n not in (name, var.depends_on)]
    if others and rng.random() < 0.3:
        other = rng.choice(others)
        spec = model.variables[other]
        if spec.depends_on is None:
            values = build_domain(spec).values
            goal[other] = values[rng.randrange(len(values))]
    return goal
