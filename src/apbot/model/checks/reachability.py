"""Which values the actions can reach: ``unreachable-value`` marks checked against the
effect tables, and the search the planner's tests use too (:func:`reachable_indices`)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from apbot.model.domain import (
    Domain,
    ValueProblem,
    build_domain,
    marked_unreachable,
    normalise,
)
from apbot.model.effects import (
    constant_table,
    default_effect,
    effect_table,
    leaf_effects,
    typed_lengths,
)
from apbot.model.problems import Problem
from apbot.model.schema import (
    AnywhereStep,
    ApplianceModel,
    GoTo,
    Step,
)


def check_unreachable_marks(model: ApplianceModel) -> Iterator[Problem]:
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


def check_reachability(model: ApplianceModel) -> Iterator[Problem]:
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
            i for i, n in enumerate(typed_lengths(domain.magnitudes, entry)) if n is not None
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
