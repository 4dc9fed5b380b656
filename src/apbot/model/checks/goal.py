"""The ``goal`` check: a goal names known variables and values they can take."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from apbot.model.checks.common import unknown_name
from apbot.model.domain import (
    ValueProblem,
    build_domain,
    normalise,
)
from apbot.model.problems import Problem
from apbot.model.schema import (
    ApplianceModel,
)


def check_goal(model: ApplianceModel, goal: Mapping[str, Any]) -> list[Problem]:
    """Goal validity (the paper's ninth check): known variables, values in their domains,
    and a programme-dependent setting valid for the goal's programme when one is given."""
    problems = []
    variables = list(model.variables)
    for name, raw in goal.items():
        path = ("goal", name)
        if name not in model.variables:
            problems.append(Problem(path, unknown_name("variable", name, variables), "goal"))
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
