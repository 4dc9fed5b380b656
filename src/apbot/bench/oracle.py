"""The oracle: the planner on the ground-truth model, executed on the ground-truth simulator.

It is the upper bound every method is measured against (its action count is the optimum used
by SPL), and running it over the suite proves every task is reachable as written. There is one
oracle, :func:`apbot.agent.oracle.run_oracle_plan`: the ``oracle`` method, the suite oracle
below and the suite checker (``apbot.bench.suite_check``) all call it, so the plan a task's
``optimal_steps`` comes from is the plan the benchmark's oracle presses.
"""

from __future__ import annotations

import statistics
import time
from dataclasses import dataclass
from typing import Any

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.oracle import OraclePlanRun, oracle_plan, run_oracle_plan
from apbot.bench.suite import Suite, SuiteAppliance, Task
from apbot.model.goal import GoalError
from apbot.plan.plan import Unreachable

__all__ = ["OraclePlanRun", "oracle_plan", "run_oracle_plan", "run_task", "run_task_with_plan"]


@dataclass(frozen=True)
class OracleResult:
    """One task run by the oracle."""

    appliance: str
    category: str
    task: str
    success: bool
    actions: int
    macro_actions: int
    planning_ms: float
    error: str = ""


def run_task(appliance: SuiteAppliance, task: Task) -> OracleResult:
    """The oracle on one task, judged on the final state of a fresh ground-truth simulator."""
    return run_task_with_plan(appliance, task)[0]


def run_task_with_plan(
    appliance: SuiteAppliance, task: Task
) -> tuple[OracleResult, OraclePlanRun | None]:
    """:func:`run_task`, and the run itself (None when the goal is invalid or unreachable)."""
    started = time.perf_counter()
    env = SimulatorEnvironment(appliance.model)
    try:
        run = run_oracle_plan(appliance.model, task.goal, env)
    except (GoalError, Unreachable) as exc:
        elapsed = (time.perf_counter() - started) * 1000
        failed = OracleResult(
            appliance.id, appliance.category, task.id, False, 0, 0, elapsed, str(exc)
        )
        return failed, None
    refused = run.refused
    success = not refused and env.simulator.satisfies(run.goal)
    error = f"refused: {refused}" if refused else "" if success else "the goal does not hold"
    result = OracleResult(
        appliance.id,
        appliance.category,
        task.id,
        success,
        len(run.plan),
        len(run.plan.macro_actions),
        run.plan.seconds * 1000,
        error,
    )
    return result, run


def run_suite_oracle(suite: Suite) -> list[OracleResult]:
    """Every task of the suite, in order."""
    return [run_task(appliance, task) for appliance, task in suite.tasks]


def summarise(results: list[OracleResult]) -> dict[str, dict[str, Any]]:
    """Per category (and ``all``): tasks, success rate, mean actions and macro actions, timing."""
    groups: dict[str, list[OracleResult]] = {}
    for result in results:
        groups.setdefault(result.category, []).append(result)
    groups["all"] = list(results)
    summary = {}
    for name, rows in groups.items():
        times = [r.planning_ms for r in rows]
        summary[name] = {
            "tasks": len(rows),
            "success_rate": sum(r.success for r in rows) / len(rows),
            "mean_actions": statistics.fmean(r.actions for r in rows),
            "mean_macro_actions": statistics.fmean(r.macro_actions for r in rows),
            "median_planning_ms": statistics.median(times),
            "worst_planning_ms": max(times),
        }
    return summary
