"""The ``size`` check: a model past :mod:`apbot.model.limits` is refused before anything is
built, so every later check may be linear in the model."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from apbot.model.domain import (
    domain_size,
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
    ApplianceModel,
)

LIMITS = f"see {SIZE_LIMITS_DOC}"


def check_sizes(model: ApplianceModel) -> Iterator[Problem]:
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
