"""One benchmark task, run in a worker: build the method's belief and goal, run the method on
the true simulator, judge the final state and write the task's record.

Kept apart from :mod:`apbot.bench.runner` (choosing the work, resuming, the run directory)
because this is everything a worker process does, and also what ``apbot run`` calls for a
single task outside any suite run.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import apbot.vision.llm_policy  # noqa: F401  registers llm-policy-image (base deps only)
from apbot.agent.environment import FeedbackMode, SimulatorEnvironment
from apbot.agent.episode import MAX_REASONING_STEPS, Episode, TaskContext, TraceEvent
from apbot.agent.registry import get_method
from apbot.bench.beliefs import BeliefSpec, belief_model, parse_belief
from apbot.bench.goals import GoalMode, MethodGoal, method_goal
from apbot.bench.memory import fits_worse
from apbot.bench.reading import BeliefFacts, belief_differences, model_digest
from apbot.bench.records import TaskRecord, record_key, spl
from apbot.bench.suite import Suite, SuiteAppliance, Task, load_suite
from apbot.llm.limits import BudgetSpent
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel


@dataclass(frozen=True)
class WorkItem:
    method: str
    appliance: str
    task: str


@dataclass(frozen=True)
class RunSettings:
    """What every task of a run shares (pinned in ``run.json``)."""

    belief: str = "read"
    seed: int = 0
    suite: str = "bundled"
    feedback: FeedbackMode = "display"
    goal: GoalMode = "read"
    learn: bool = False


_SUITES: dict[str, Suite] = {}


def cached_suite(name: str) -> Suite:
    """The suite, loaded once per process (forked workers inherit the main process's copy)."""
    if name not in _SUITES:
        _SUITES[name] = load_suite(name)
    return _SUITES[name]


def _find(suite: str, appliance_id: str, task_id: str) -> tuple[SuiteAppliance, Task]:
    appliance = cached_suite(suite).get(appliance_id)
    for task in appliance.tasks:
        if task.id == task_id:
            return appliance, task
    raise KeyError(f"appliance {appliance_id!r} has no task {task_id!r}")


@lru_cache(maxsize=256)
def _belief(
    suite: str, appliance_id: str, spec: BeliefSpec, seed: int
) -> tuple[ApplianceModel, tuple[str, ...]]:
    """The belief model for an appliance (models are frozen, so one copy serves every task)."""
    model, faults = belief_model(cached_suite(suite).get(appliance_id), spec, seed)
    return model, tuple(faults)


@lru_cache(maxsize=256)
def _about_belief(suite: str, appliance_id: str, spec: BeliefSpec, seed: int) -> BeliefFacts:
    """The belief's hash and, for a read one, its differences from the truth (for reports)."""
    model, _faults = _belief(suite, appliance_id, spec, seed)
    truth = cached_suite(suite).get(appliance_id).model
    differences = belief_differences(model, truth) if spec.kind == "read" else []
    return BeliefFacts(model_digest(model), tuple(differences))


def _optimal(appliance: SuiteAppliance, task: Task, goal: dict[str, Any]) -> int:
    """The task's stored optimum, or the planner's on the ground truth when it is missing."""
    if task.optimal_steps is not None:
        return task.optimal_steps
    from apbot.plan.plan import plan

    return len(plan(appliance.model, None, goal))


def _describe(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {exc}"


def run_one(
    method: str,
    belief: str,
    seed: int,
    appliance_id: str,
    task_id: str,
    suite: str,
    feedback: FeedbackMode = "display",
    goal: GoalMode = "given",
) -> TaskRecord:
    """Run one method on one task and judge the result on the true simulator.

    Success means the task's goal (normalised on the true model) holds in the environment's
    final state and the method stayed within the reasoning-step limit; what the method claims
    is recorded but not trusted. An exception in the method gives a failed record.
    """
    settings = RunSettings(belief, seed, suite, feedback, goal)
    return run_item(WorkItem(method, appliance_id, task_id), settings)[0]


def run_item(
    item: WorkItem, settings: RunSettings, learnt: ApplianceModel | None = None, index: int = 0
) -> tuple[TaskRecord, ApplianceModel | None]:
    """:func:`run_one` on a work item; with ``learnt``, the method starts from that belief
    (``index`` tasks before this one left it). Also returns the belief the method ended with."""
    appliance, task = _find(settings.suite, item.appliance, item.task)
    spec = parse_belief(settings.belief)
    return run_task_learning(
        appliance,
        task,
        item.method,
        settings.belief,
        settings.seed,
        belief_of=lambda s: _belief(settings.suite, appliance.id, s, settings.seed),
        feedback=settings.feedback,
        goal_mode=settings.goal,
        facts=lambda: _about_belief(settings.suite, appliance.id, spec, settings.seed),
        learnt=learnt,
        index=index,
    )


def run_task(
    appliance: SuiteAppliance,
    task: Task,
    method: str,
    belief: str = "true",
    seed: int = 0,
    observer: Callable[[TraceEvent], None] | None = None,
    belief_of: Callable[[BeliefSpec], tuple[ApplianceModel, Any]] | None = None,
    feedback: FeedbackMode = "display",
    goal: GoalMode = "given",
) -> TaskRecord:
    """:func:`run_one` on objects: also for a task that is not in a suite (``apbot run``).

    ``observer`` sees every trace event as it happens; ``belief_of`` builds (or fetches a
    cached) belief model for the parsed belief spec; ``goal`` says whether the method gets
    the task's goal or reads it from the instruction. Raises :class:`ValueError` before
    anything runs when the stored goal is not a reachable state of the true appliance.
    """
    return run_task_learning(
        appliance, task, method, belief, seed, observer, belief_of, feedback, goal
    )[0]


def run_task_learning(
    appliance: SuiteAppliance,
    task: Task,
    method: str,
    belief: str = "true",
    seed: int = 0,
    observer: Callable[[TraceEvent], None] | None = None,
    belief_of: Callable[[BeliefSpec], tuple[ApplianceModel, Any]] | None = None,
    feedback: FeedbackMode = "display",
    goal_mode: GoalMode = "given",
    facts: Callable[[], BeliefFacts] | None = None,
    learnt: ApplianceModel | None = None,
    index: int = 0,
) -> tuple[TaskRecord, ApplianceModel | None]:
    """:func:`run_task`, optionally from a learnt belief, returning the belief it ended with."""
    from apbot.model.goal import GoalError
    from apbot.plan.plan import Unreachable

    try:
        goal = parse_goal(appliance.model, task.goal)
        optimal = _optimal(appliance, task, goal)
    except (GoalError, Unreachable) as exc:
        raise ValueError(
            f"{appliance.id}/{task.id}: the goal is not reachable on the appliance: {exc}"
        ) from None
    started = time.perf_counter()
    spec = parse_belief(belief)
    chosen = get_method(method)
    env: Any = (
        image_environment(appliance, appliance.model.actions, seed)
        if feedback == "image"
        else SimulatorEnvironment(appliance.model, feedback)
    )
    episode, error = Episode(), ""
    faults: tuple[str, ...] | list[str] = ()
    context: TaskContext | None = None
    asked = MethodGoal(dict(task.goal))
    digest = ""
    about: BeliefFacts | None = None
    try:
        if chosen.uses_truth:
            model, faults = appliance.model, ()
        elif belief_of is not None:
            model, faults = belief_of(spec)
        else:
            model, faults = belief_model(appliance, str(spec), seed)
        if not chosen.uses_truth:  # the oracle plans on the truth, to the stored goal
            asked = _asked(goal_mode, model, appliance, task)
            if learnt is not None:  # the learnt belief, unless it fits the request worse
                learnt_asked = _asked(goal_mode, learnt, appliance, task)
                if fits_worse(learnt, learnt_asked, model, asked):
                    learnt = None
                else:
                    model, faults, asked = learnt, (), learnt_asked
        about = facts() if facts is not None and learnt is None and not chosen.uses_truth else None
        digest = about.digest if about is not None else model_digest(model)
    except BudgetSpent:
        raise
    except Exception as exc:
        error = f"error: building the belief: {_describe(exc)}"
    else:
        if feedback == "image" and list(model.actions) != list(appliance.model.actions):
            env = image_environment(appliance, model.actions, seed)  # ground the belief's names
        if asked.goal is None:
            episode = Episode(failure=asked.error)
        else:
            context = TaskContext(
                appliance.id,
                appliance.category,
                task.id,
                task.instruction,
                asked.goal,
                model,
                appliance.manual,
                tuple(env.actions),
                goal_read=goal_mode == "read" and not chosen.uses_truth,
                observer=observer,
            )
            try:
                result = chosen.run(context, env)
                if not isinstance(result, Episode):
                    raise TypeError(f"method returned {type(result).__name__}, not an Episode")
                episode = result
            except BudgetSpent:
                raise  # not the task's failure: the run stops here and this task runs again later
            except Exception as exc:
                error = f"error: {_describe(exc)}"
    limit = context.max_reasoning_steps if context is not None else MAX_REASONING_STEPS
    final = {name: env.simulator.value(name) for name in goal}
    reached = all(final[name] == value for name, value in goal.items())
    within = episode.reasoning_steps <= limit
    success = not error and reached and within
    failure = "" if success else error or _failure(episode, goal, final, reached, limit)
    record = TaskRecord(
        key=record_key(method, str(spec), appliance.id, task.id),
        method=method,
        belief=str(spec),
        feedback=feedback,
        appliance=appliance.id,
        category=appliance.category,
        task=task.id,
        instruction=task.instruction,
        goal=dict(task.goal),
        goal_variables=len(task.goal),
        success=success,
        claimed_success=episode.claimed_success,
        reasoning_steps=episode.reasoning_steps,
        execution_steps=env.steps,
        optimal_steps=optimal,
        spl=spl(success, optimal, env.steps),
        failure=failure,
        repairs=list(episode.repairs),
        faults=list(faults),
        final_values=final,
        trace=[event.to_dict() for event in episode.trace],
        timings={"seconds": round(time.perf_counter() - started, 6)},
        llm_usage={
            k: episode.llm_usage.get(k, 0) + asked.usage.get(k, 0)
            for k in {**episode.llm_usage, **asked.usage}
        },
        goal_mode=goal_mode if not chosen.uses_truth else "given",
        parsed_goal=asked.parsed,
        goal_exact=asked.exact,
        goal_outside=list(asked.outside),
        belief_hash=digest,
        belief_diff=list(about.differences) if about is not None else [],
        learnt_from=index if learnt is not None else 0,
    )
    return record, episode.belief


def _asked(
    mode: GoalMode, model: ApplianceModel, appliance: SuiteAppliance, task: Task
) -> MethodGoal:
    """The goal a method working from ``model`` gets for ``task``."""
    return method_goal(
        mode, model, task.instruction, appliance.manual, dict(task.goal), appliance.model
    )


def image_environment(appliance: SuiteAppliance, actions: Iterable[str], seed: int) -> Any:
    """Image mode: the appliance as a rendered panel, grounded once per appliance and process
    (``apbot.vision``; needs the ``vision`` extra)."""
    from apbot.vision.mode import image_environment as build

    return build(appliance, list(actions), seed)


def _failure(
    episode: Episode, goal: dict[str, Any], final: dict[str, Any], reached: bool, limit: int
) -> str:
    """One line saying why a run failed, the method's own reason first."""
    parts = []
    if episode.reasoning_steps > limit:
        parts.append(f"over the reasoning-step limit ({episode.reasoning_steps} > {limit})")
    if episode.failure:
        parts.append(episode.failure)
    if not reached:
        wrong = ", ".join(
            f"{name}={final[name]!r} (want {value!r})"
            for name, value in goal.items()
            if final[name] != value
        )
        claim = "claimed success but " if episode.claimed_success and not episode.failure else ""
        parts.append(f"{claim}goal not met: {wrong}")
    return "; ".join(parts)
