"""The summary scripts and the report read: its shape, its means and its p-values."""

from __future__ import annotations

import json

import pytest

from apbot.bench.metrics import chi_square_p, pvalues, summarise
from apbot.bench.records import TaskRecord, record_key


def record(
    method: str,
    task: str,
    success: bool,
    *,
    category: str = "kettle",
    reasoning: int = 2,
    execution: int = 4,
    optimal: int = 4,
    goal_variables: int = 2,
) -> TaskRecord:
    appliance = f"{category}_1"
    return TaskRecord(
        key=record_key(method, "true", appliance, task),
        method=method,
        belief="true",
        appliance=appliance,
        category=category,
        task=task,
        instruction="do the thing",
        goal={f"v{i}": "x" for i in range(goal_variables)},
        goal_variables=goal_variables,
        success=success,
        claimed_success=success,
        reasoning_steps=reasoning,
        execution_steps=execution,
        optimal_steps=optimal,
        spl=optimal / max(optimal, execution) if success else 0.0,
    )


def test_summary_shape_and_figures() -> None:
    records = [
        record("a", "t1", True, execution=8),
        record("a", "t2", False, reasoning=40, execution=30),
        record("a", "t3", True, category="microwave", goal_variables=4),
        record("b", "t1", True),
    ]
    summary = summarise(records)
    assert set(summary) == {"belief", "methods", "goal_variables", "pvalues"}
    assert summary["belief"] == "true"
    a = summary["methods"]["a"]
    assert set(a) == {"overall", "categories"}
    assert set(a["categories"]) == {"kettle", "microwave"}
    assert a["overall"] == {
        "sr": 0.666667,
        "spl": 0.5,
        "n": 3,
        # 40 reasoning steps count as the limit, 25
        "reasoning_steps": round((2 + 25 + 2) / 3, 6),
        "execution_steps": 14.0,
    }
    assert a["categories"]["kettle"]["n"] == 2
    assert summary["goal_variables"]["a"] == {"2": {"sr": 0.5, "n": 2}, "4": {"sr": 1.0, "n": 1}}
    assert summary["pvalues"]["a"]["a"] == 1.0 and summary["pvalues"]["a"]["b"] == 1.0


def test_summary_is_deterministic_whatever_the_record_order() -> None:
    records = [record(m, f"t{i}", (i + len(m)) % 3 > 0) for m in ("x", "yy") for i in range(9)]
    once = json.dumps(summarise(records), sort_keys=True)
    assert once == json.dumps(summarise(list(reversed(records))), sort_keys=True)


def test_identical_outcomes_give_p_one() -> None:
    outcomes = [True, False, True, True, False] * 4
    assert chi_square_p(outcomes, list(outcomes)) == 1.0
    assert chi_square_p([True] * 10, [True] * 10) == 1.0  # degenerate: no failures at all


def test_very_different_outcomes_give_a_small_p() -> None:
    good = [True] * 45 + [False] * 5
    bad = [True] * 10 + [False] * 40
    p = chi_square_p(good, bad)
    assert 0 < p < 1e-6
    assert chi_square_p(good, good[:40] + [False] * 10) > 0.05  # 45/50 vs 40/50: not significant


def test_pvalue_matrix_is_symmetric_and_uses_only_shared_tasks() -> None:
    a = [record("a", f"t{i}", True) for i in range(30)]
    b = [record("b", f"t{i}", i >= 25) for i in range(30)]
    c = [record("c", f"t{i}", True) for i in range(30)] + [
        record("c", f"extra{i}", False) for i in range(30)
    ]  # tasks only c ran: ignored
    matrix = pvalues({"a": a, "b": b, "c": c})
    assert list(matrix) == ["a", "b", "c"]
    assert all(matrix[m][m] == 1.0 for m in matrix)
    assert matrix["a"]["c"] == 1.0
    assert matrix["a"]["b"] == matrix["b"]["a"] < 0.001
    assert matrix["b"]["c"] == matrix["c"]["b"] == matrix["a"]["b"]


@pytest.mark.parametrize("belief", [None, "faulty:0.2"])
def test_belief_is_reported(belief: str | None) -> None:
    summary = summarise([record("a", "t1", True)], belief=belief)
    assert summary["belief"] == (belief or "true")
