"""Benchmark figures from task records: the paper's success rate, SPL and step counts.

:func:`summarise` gives the ``summary.json`` that scripts, CI and the report read::

    {"belief": str,
     "methods": {METHOD: {"overall": FIGURES, "categories": {CATEGORY: FIGURES}}},
     "goal_variables": {METHOD: {"1": {"sr", "n"}, ...}},
     "pvalues": {A: {B: p}}}

where FIGURES is ``{"sr", "spl", "reasoning_steps", "execution_steps", "n"}``. Steps are means
over every task, failures included, as in the paper; reasoning steps are capped at the limit
(a run stopped for exceeding it counts the limit). Floats are rounded to 6 decimals so the
file is byte-identical for identical records — except p-values, kept to 6 significant digits
so a very small p stays distinguishable from 0 (and on a log scale).
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Sequence
from statistics import fmean
from typing import Any

from apbot.agent.episode import MAX_REASONING_STEPS
from apbot.bench.records import TaskRecord

DIGITS = 6


def _round(value: float) -> float:
    return round(float(value), DIGITS)


def figures(records: Sequence[TaskRecord]) -> dict[str, float | int]:
    """SR, mean SPL, mean reasoning (capped) and execution steps, and the task count."""
    if not records:
        return {"sr": 0.0, "spl": 0.0, "reasoning_steps": 0.0, "execution_steps": 0.0, "n": 0}
    return {
        "sr": _round(fmean(r.success for r in records)),
        "spl": _round(fmean(r.spl for r in records)),
        "reasoning_steps": _round(
            fmean(min(r.reasoning_steps, MAX_REASONING_STEPS) for r in records)
        ),
        "execution_steps": _round(fmean(r.execution_steps for r in records)),
        "n": len(records),
    }


def chi_square_p(a: Sequence[bool], b: Sequence[bool]) -> float:
    """p-value of a chi-square test of independence between method and outcome (2×2 table).

    The table is ``[[successes of a, failures of a], [successes of b, failures of b]]``, tested
    with ``scipy.stats.chi2_contingency`` (Yates-corrected, as scipy does for 2×2), following
    the paper. When a row or column is empty (e.g. both methods always succeed) the expected
    counts are zero and the statistic is undefined; the methods' outcomes are then
    indistinguishable by this test, so the p-value is 1.0 — as it is for identical outcomes.

    >>> chi_square_p([True] * 5, [True] * 5)
    1.0
    >>> chi_square_p([True] * 40 + [False] * 10, [True] * 10 + [False] * 40) < 1e-6
    True
    """
    from scipy.stats import chi2_contingency

    table = [[sum(a), len(a) - sum(a)], [sum(b), len(b) - sum(b)]]
    if table[0] == table[1] or 0 in (
        sum(table[0]),
        sum(table[1]),
        table[0][0] + table[1][0],
        table[0][1] + table[1][1],
    ):
        return 1.0
    return float(f"{chi2_contingency(table).pvalue:.6g}")


def _task_id(record: TaskRecord) -> str:
    return f"{record.appliance}/{record.task}"


def pvalues(by_method: dict[str, list[TaskRecord]]) -> dict[str, dict[str, float]]:
    """Symmetric p-value matrix (diagonal 1.0) over the tasks each pair of methods both ran."""
    outcomes = {m: {_task_id(r): r.success for r in rows} for m, rows in by_method.items()}
    names = sorted(outcomes)
    matrix: dict[str, dict[str, float]] = {m: {} for m in names}
    for i, a in enumerate(names):
        matrix[a][a] = 1.0
        for b in names[i + 1 :]:
            shared = sorted(outcomes[a].keys() & outcomes[b].keys())
            p = chi_square_p([outcomes[a][t] for t in shared], [outcomes[b][t] for t in shared])
            matrix[a][b] = matrix[b][a] = p
    return matrix


def summarise(records: Iterable[TaskRecord], belief: str | None = None) -> dict[str, Any]:
    """The summary of a run (see the module docstring); ``belief`` defaults to the records'."""
    rows = sorted(records, key=lambda r: r.key)
    by_method: dict[str, list[TaskRecord]] = defaultdict(list)
    for record in rows:
        by_method[record.method].append(record)
    if belief is None:
        beliefs = sorted({r.belief for r in rows})
        belief = beliefs[0] if len(beliefs) == 1 else ",".join(beliefs)
    methods: dict[str, Any] = {}
    goal_variables: dict[str, Any] = {}
    for method in sorted(by_method):
        mine = by_method[method]
        categories: dict[str, list[TaskRecord]] = defaultdict(list)
        sizes: dict[int, list[TaskRecord]] = defaultdict(list)
        for record in mine:
            categories[record.category].append(record)
            sizes[record.goal_variables].append(record)
        methods[method] = {
            "overall": figures(mine),
            "categories": {c: figures(categories[c]) for c in sorted(categories)},
        }
        usage: dict[str, int] = defaultdict(int)
        for record in mine:
            for name, value in record.llm_usage.items():
                usage[name] += value
        if usage:  # tokens summed over the run (the LLM methods and readers)
            methods[method]["llm_usage"] = dict(sorted(usage.items()))
        goal_variables[method] = {
            str(n): {"sr": _round(fmean(r.success for r in sizes[n])), "n": len(sizes[n])}
            for n in sorted(sizes)
        }
    return {
        "belief": belief,
        "methods": methods,
        "goal_variables": goal_variables,
        "pvalues": pvalues(dict(by_method)),
    }
