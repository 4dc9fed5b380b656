"""The ``reference`` and ``domain`` checks: every name resolves, every variable's domain builds."""

from __future__ import annotations

from collections.abc import Iterator

from apbot.model.checks.common import Names, unknown_name
from apbot.model.domain import (
    Domain,
    DomainError,
    build_domain,
)
from apbot.model.problems import PathPart, Problem
from apbot.model.schema import (
    TEMPLATE_FIELD,
    ApplianceModel,
    DiscreteVariable,
)
from apbot.model.values import closest_matches, preview


def check_references(model: ApplianceModel) -> Iterator[Problem]:
    controls = Names(c.id for c in model.controls)
    variables = Names(model.variables)
    actions = Names(model.actions)
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
                    ("actions", name, key), unknown_name("control", cid, controls), "reference"
                )
    for name, var in model.variables.items():
        if var.depends_on is not None and var.depends_on not in variables:
            yield Problem(
                ("variables", name, "depends_on"),
                unknown_name("variable", var.depends_on, variables),
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
                        (*path, "actions", a),
                        unknown_name("action", action, actions),
                        "unknown-action",
                    )
            if step.variable is not None and step.variable not in variables:
                yield Problem(
                    (*path, "variable"),
                    unknown_name("variable", step.variable, variables),
                    "reference",
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
                        (*path, key), unknown_name("variable", target, variables), "reference"
                    )
    for i, entry in enumerate(model.anywhere):
        apath: tuple[PathPart, ...] = ("anywhere", i)
        if not entry.actions:
            yield Problem((*apath, "actions"), "an anywhere entry needs an action", "empty-action")
        for a, action in enumerate(entry.actions):
            if action not in actions:
                yield Problem(
                    (*apath, "actions", a),
                    unknown_name("action", action, actions),
                    "unknown-action",
                )
        if entry.variable is not None and entry.variable not in variables:
            yield Problem(
                (*apath, "variable"),
                unknown_name("variable", entry.variable, variables),
                "reference",
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
                yield Problem(
                    (*apath, key), unknown_name("variable", target, variables), "reference"
                )
    for g, guard in enumerate(model.guards):
        for name in guard.when:
            if name not in variables:
                yield Problem(
                    ("guards", g, "when", name),
                    unknown_name("variable", name, variables),
                    "reference",
                )
        for a, action in enumerate(guard.only):
            if action not in actions:
                yield Problem(
                    ("guards", g, "only", a),
                    unknown_name("action", action, actions),
                    "unknown-action",
                )
    for name in model.display.indicators:
        if name not in variables:
            yield Problem(
                ("display", "indicators"), unknown_name("variable", name, variables), "reference"
            )
    for field in TEMPLATE_FIELD.findall(model.display.idle):
        if field not in variables:
            yield Problem(
                ("display", "idle"), unknown_name("variable", field, variables), "display"
            )
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


def check_domains(model: ApplianceModel) -> tuple[dict[str, list[Domain]], list[Problem]]:
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
