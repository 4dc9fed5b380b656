"""What an agent that learns (``apbot bench --learn``) keeps of an appliance between requests.

A repair is a hypothesis fitted to one task's walk on the panel; kept blindly, one that was
right for that task is wrong for the next (a value list that stops where that task's goal
was, a precondition seen once), and a household robot must not get worse by remembering.
So the learnt belief is evidence-weighted against the manual's reading, with honest inputs
only — the agent's own verdict on its episode, the user's sentence read on each belief, and
the planner on each belief:

* a belief is carried to the next request only from an episode the agent itself ended
  claiming success; after a declared failure the repairs it made (or started from) are
  unconfirmed, and the next request starts again from the manual's reading;
* at the start of a request the learnt belief is dropped back to the manual's reading when
  it fits the request worse than the manual does: the sentence names fewer settings on it
  (a repair renamed the values the user speaks of), or no plan reaches the goal on it while
  one does on the manual's reading (a kept guard or restriction that keeps the goal apart).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from apbot.bench.goals import MethodGoal
from apbot.model.goal import GoalError
from apbot.model.schema import ApplianceModel


def keeps_belief(claimed_success: bool, after: ApplianceModel | None) -> bool:
    """Whether the belief an episode ended with is carried to the next request: only one the
    agent ended with a claimed success (its repairs then led to a goal it saw hold)."""
    return after is not None and claimed_success


def fits_worse(
    learnt: ApplianceModel,
    learnt_goal: MethodGoal,
    manual: ApplianceModel,
    manual_goal: MethodGoal,
) -> str:
    """Why the learnt belief fits this request worse than the manual's reading ('' when it
    does not): the sentence reads to fewer settings on it, or it has no plan where the
    manual's reading has one."""
    if manual_goal.goal is None:
        return ""
    if learnt_goal.goal is None:
        return "the request cannot be read on the learnt belief"
    lost = sorted(set(manual_goal.goal) - set(learnt_goal.goal))
    if len(learnt_goal.goal) < len(manual_goal.goal):
        return f"the request names {', '.join(lost) or 'fewer settings'} only on the manual"
    if _plannable(learnt, learnt_goal.goal) is False and _plannable(manual, manual_goal.goal):
        return "no plan reaches the goal on the learnt belief"
    return ""


def _plannable(model: ApplianceModel, goal: Mapping[str, Any]) -> bool | None:
    """Whether a plan reaches ``goal`` from the model's initial state (None: cannot tell — a
    value outside the model, which the agent explores for, or a search that ran out)."""
    from apbot.plan.plan import Unreachable, plan

    try:
        plan(model, None, goal)
    except Unreachable as exc:
        return None if exc.budget_hit else False
    except (GoalError, ValueError, TypeError):
        return None
    return True
