"""The oracle: the planner on the ground-truth model, executed on the ground-truth simulator.

It is the upper bound every method is measured against (its action count is the optimum used
by SPL), and running it over the suite proves every task is reachable as written.
"""

from __future__ import annotations

import statistics
import time
from dataclasses import dataclass
from typing import Any

from apbot.bench.suite import Suite, SuiteAppliance, Task
from apbot.model.goal import parse_goal
from apbot.plan.plan import Unreachable, plan
from apbot.sim.simulator import Simulator


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
    """Plan on the ground truth, press every action on a fresh simulator, judge the final state."""
    started = time.perf_counter()
    try:
        goal = parse_goal(appliance.model, task.goal)
        found = plan(appliance.model, None, goal)
    except (Unreachable, ValueError) as exc:
        return OracleResult(
            appliance.id,
            appliance.category,
            task.id,
            False,
            0,
            0,
            (time.perf_counter() - started) * 1000,
            str(exc),
        )
    planning_ms = (time.perf_counter() - started) * 1000
    simulator = Simulator(appliance.model)
    refused = [a.name for a in found.actions if not simulator.step(a.name, a.seconds).accepted]
    success = not refused and simulator.satisfies(goal)
    return OracleResult(
        appliance.id,
        appliance.category,
        task.id,
        success,
        len(found),
        len(found.macro_actions),
        planning_ms,
        f"refused: {refused}" if refused else "",
    )


def run_oracle(suite: Suite) -> list[OracleResult]:
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
