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

The checks live in :mod:`apbot.model.checks`, one module per concern; this module runs them
in order and is where callers import them from.
"""

from __future__ import annotations

from apbot.model.checks.goal import check_goal
from apbot.model.checks.reachability import (
    check_reachability,
    check_unreachable_marks,
    reachable_indices,
)
from apbot.model.checks.references import check_domains, check_references
from apbot.model.checks.sizes import check_sizes
from apbot.model.checks.steps import check_anywhere, check_procedure_options, check_steps
from apbot.model.checks.structure import (
    CYCLE_UNITS,
    check_controls,
    check_coverage,
    check_cycles,
    check_duplicates,
    check_guards,
)
from apbot.model.problems import Problem
from apbot.model.schema import ApplianceModel

__all__ = ["CYCLE_UNITS", "check_goal", "check_model", "reachable_indices"]


def check_model(model: ApplianceModel) -> list[Problem]:
    """Every problem of the model; errors make it unusable, warnings are advice."""
    too_large = list(check_sizes(model))
    if too_large:
        return too_large  # every later check is linear in the model; past a limit, stop here
    problems = list(check_references(model))
    domains, domain_problems = check_domains(model)
    problems += domain_problems
    if any(p.severity == "error" for p in problems):
        return problems  # later checks need resolvable names and buildable domains
    problems += check_steps(model, domains)
    problems += check_procedure_options(model)
    problems += check_anywhere(model, domains)
    problems += check_coverage(model)
    problems += check_duplicates(model)
    problems += check_guards(model)
    problems += check_controls(model)
    problems += check_cycles(model)
    problems += check_unreachable_marks(model)
    if not any(p.severity == "error" for p in problems):
        problems += check_reachability(model)
    return problems
