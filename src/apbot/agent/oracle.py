"""The oracle's plan and presses: the planner on a model, pressed open loop on an environment.

It lives with the agent, below the benchmark: the ``oracle`` method (``apbot.agent.methods``)
presses it, and the benchmark's suite oracle and checker (``apbot.bench.oracle``,
``apbot.bench.suite_check``) call the same function, so the plan a task's ``optimal_steps``
comes from is the plan the oracle method presses.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from apbot.agent.environment import Environment, Feedback
from apbot.model.goal import Goal, parse_goal
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import MacroAction, Plan, PlannedAction, plan

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
