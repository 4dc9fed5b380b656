"""The oracle: the planner on the ground-truth model, executed on the ground-truth simulator.

It is the upper bound every method is measured against (its action count is the optimum used
by SPL), and running it over the suite proves every task is reachable as written. There is one
oracle, :func:`run_oracle_plan`: the ``oracle`` method (``apbot.agent.methods``), the suite
oracle below and the suite checker (``apbot.bench.suite_check``) all call it, so the plan a
task's ``optimal_steps`` comes from is the plan the benchmark's oracle presses.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from apbot.agent.environment import Environment, Feedback, SimulatorEnvironment
from apbot.bench.suite import Suite, SuiteAppliance, Task
from apbot.model.goal import Goal, GoalError, parse_goal
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import MacroAction, Plan, PlannedAction, Unreachable, plan

OnMacro = Callable[[MacroAction], None]
OnAction = Callable[[PlannedAction, Feedback], None]


@dataclass
class OraclePlanRun:
    """One oracle run: the canonical goal, the plan, and the feedback of every action pressed."""

    goal: Goal
    plan: Plan
    feedback: list[Feedback] = field(default_factory=list)

    @property
    def refused(self) -> list[str]:
        """The planned actions the environment refused (none, on the model planned on)."""
        return [
            a.name for a, f in zip(self.plan.actions, self.feedback, strict=True) if not f.accepted
        ]


def oracle_plan(model: ApplianceModel, goal: Mapping[str, Any]) -> tuple[Goal, Plan]:
    """The oracle's plan: the shortest plan on ``model`` from its initial state.

    Raises :class:`GoalError` for a goal the model cannot express and :class:`Unreachable`
    when no action sequence reaches it.
    """
    canonical = parse_goal(model, goal)
    return canonical, plan(model, None, canonical)


def run_oracle_plan(
    model: ApplianceModel,
    goal: Mapping[str, Any],
    env: Environment,
    on_macro: OnMacro | None = None,
    on_action: OnAction | None = None,
) -> OraclePlanRun:
    """Plan on ``model``, reset ``env`` and press every planned action in order, open loop.

    ``on_macro`` is called before each macro action and ``on_action`` after each press (the
    ``oracle`` method logs its trace through them). Raises like :func:`oracle_plan`.
    """
    canonical, found = oracle_plan(model, goal)
    run = OraclePlanRun(canonical, found)
    env.reset()
    for macro in found.macro_actions:
        if on_macro is not None:
            on_macro(macro)
        for action in macro.actions:
            feedback = env.step(action.name, action.seconds)
            run.feedback.append(feedback)
            if on_action is not None:
                on_action(action, feedback)
    return run


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
