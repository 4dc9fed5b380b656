"""Checks of a suite appliance beyond its model: panel, manual, tasks, and oracle reachability.

Every task must be reachable: the oracle (``apbot.bench.oracle``), executed on the
ground-truth simulator, has to reach the task's goal. The stored ``optimal_steps`` must equal
the oracle's plan length, so a changed model cannot silently keep stale optimal counts, and
the goal must not be met by an obviously different operation (``apbot.bench.goal_checks``).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from apbot.bench.goal_checks import CHECKS, goal_findings
from apbot.bench.newcats_goal_sizes import DEVELOPMENT_GOAL_VARIABLES
from apbot.bench.oracle import oracle_plan, run_task_with_plan
from apbot.bench.suite import (
    GOAL_VARIABLES,
    SuiteAppliance,
    Task,
    TaskFile,
)
from apbot.model.goal import Goal, GoalError, parse_goal
from apbot.model.problems import Problem
from apbot.model.yaml_text import dump_yaml, read_yaml
from apbot.plan.plan import Unreachable
from apbot.sim.checks import check_model

MANUAL_WORDS = (600, 6000)  # a short leaflet to a long real manual (issue 12: 2–6k words)


def check_appliance(appliance: SuiteAppliance, plan_tasks: bool = True) -> list[Problem]:
    """Every problem with one appliance; an empty list means it is ready for the benchmark."""
    problems = check_model(appliance.model)
    if any(p.severity == "error" for p in problems):
        return problems
    problems += list(_panel(appliance))
    problems += list(_manual(appliance))
    problems += list(_tasks(appliance, plan_tasks))
    return problems


def _panel(appliance: SuiteAppliance) -> Iterator[Problem]:
    layout = appliance.layout
    width, height = layout.canvas
    model_controls = {c.id: c for c in appliance.model.controls}
    drawn = {c.id: c for c in layout.controls}
    for cid in model_controls.keys() - drawn.keys():
        yield Problem(("panel", "controls"), f"control {cid!r} of the model is not drawn", "panel")
    for cid in drawn.keys() - model_controls.keys():
        yield Problem(
            ("panel", "controls"), f"control {cid!r} is drawn but not in the model", "panel"
        )
    boxes = [("display", layout.display)] + [(c.id, c.box) for c in layout.controls]
    for name, (x0, y0, x1, y1) in boxes:
        if not (0 <= x0 < x1 <= width and 0 <= y0 < y1 <= height):
            yield Problem(
                ("panel", name),
                f"box {[x0, y0, x1, y1]} is not inside the "
                f"{width}x{height} canvas with positive size",
                "panel",
            )
    for i, (name_a, a) in enumerate(boxes):
        for name_b, b in boxes[i + 1 :]:
            if a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]:
                yield Problem(("panel", name_b), f"box overlaps {name_a!r}", "panel")
    for control in layout.controls:
        model_control = model_controls.get(control.id)
        if model_control is not None and model_control.label != control.label:
            yield Problem(
                ("panel", control.id),
                f"label {control.label!r} differs from the model's {model_control.label!r}",
                "panel",
            )


def _manual(appliance: SuiteAppliance) -> Iterator[Problem]:
    words = appliance.manual_words
    low, high = MANUAL_WORDS
    if not low <= words <= high:
        yield Problem(("manual",), f"{words} words; a manual has {low} to {high}", "manual")


def _tasks(appliance: SuiteAppliance, plan_tasks: bool) -> Iterator[Problem]:
    known = {**GOAL_VARIABLES, **DEVELOPMENT_GOAL_VARIABLES}
    wanted = known.get(appliance.category)
    if wanted is None:
        yield Problem(
            ("model", "appliance", "category"),
            f"unknown category {appliance.category!r}; use one of {sorted(known)}",
            "suite",
        )
    if appliance.id != appliance.directory.name:
        yield Problem(
            ("model", "appliance", "id"),
            f"id {appliance.id!r} differs from the directory name {appliance.directory.name!r}",
            "suite",
        )
    seen: set[str] = set()
    for i, task in enumerate(appliance.tasks):
        path = ("tasks", i)
        if task.id in seen:
            yield Problem((*path, "id"), f"task id {task.id!r} repeats", "suite")
        seen.add(task.id)
        if wanted is not None and len(task.goal) != wanted:
            yield Problem(
                (*path, "goal"),
                f"{len(task.goal)} goal variables; {appliance.category} tasks have {wanted}",
                "suite",
            )
        try:
            goal = parse_goal(appliance.model, task.goal)
        except GoalError as exc:
            for problem in exc.problems:
                yield Problem((*path, *problem.path), problem.message, "goal")
            continue
        yield from _allow_keys(task, path)
        if plan_tasks:
            yield from _oracle(appliance, task, goal, path)


def _allow_keys(task: Task, path: tuple[str | int, ...]) -> Iterator[Problem]:
    for key, reason in task.allow.items():
        check, _, variable = key.partition(":")
        if check not in CHECKS or (check == "free") != bool(variable):
            yield Problem(
                (*path, "allow", key),
                f"{task.id}: unknown finding {key!r}; use one of "
                "'quick-start', 'start-only' or 'free:VARIABLE'",
                "suite",
            )
        elif variable and variable not in task.goal:
            yield Problem(
                (*path, "allow", key), f"{task.id}: {variable!r} is not in the goal", "suite"
            )
        if not reason.strip():
            yield Problem((*path, "allow", key), f"{task.id}: say why it is allowed", "suite")


def _oracle(
    appliance: SuiteAppliance, task: Task, goal: Goal, path: tuple[str | int, ...]
) -> Iterator[Problem]:
    """The oracle reaches the goal, ``optimal_steps`` is its length, the goal is specific."""
    result, run = run_task_with_plan(appliance, task)
    if run is None or not result.success:
        yield Problem((*path, "goal"), f"{task.id}: the oracle fails: {result.error}", "oracle")
        return
    if result.actions == 0:
        yield Problem(
            (*path, "goal"), f"{task.id}: the goal already holds in the initial state", "suite"
        )
    if task.optimal_steps != result.actions:
        yield Problem(
            (*path, "optimal_steps"),
            f"{task.id}: stored {task.optimal_steps}, the oracle "
            f"finds {result.actions}; run `apbot suite fill-optimal`",
            "oracle",
        )
    found = goal_findings(appliance.model, goal, run.plan)
    for finding in found:
        if finding.key not in task.allow:
            yield Problem(
                (*path, "goal"),
                f"{task.id}: {finding.message} (fix the task, or record why it is wanted "
                f"under allow: {{{finding.key!r}: REASON}})",
                finding.key,
            )
    keys = {f.key for f in found}
    for key in task.allow:
        if key not in keys and key.partition(":")[0] in CHECKS:
            yield Problem(
                (*path, "allow", key),
                f"{task.id}: nothing to allow any more ({key} does not fire); remove it",
                "suite",
            )


def optimal_steps(appliance: SuiteAppliance, task: Task) -> int:
    """The oracle's optimal action count for a task (its plan on the ground truth)."""
    return len(oracle_plan(appliance.model, task.goal)[1])


class FillError(ValueError):
    """A task whose optimal count cannot be computed; the message names the task and why."""


def fill_optimal(appliance: SuiteAppliance) -> int:
    """Rewrite ``tasks.yaml`` with the planner's optimal action counts; returns how many changed.

    The file is rewritten from its parsed form, so comments in it are not kept. A task whose
    goal the model cannot express or reach raises :class:`FillError` before anything is
    written, so one bad task never leaves the file half rewritten.
    """
    path: Path = appliance.directory / "tasks.yaml"
    data = TaskFile.model_validate(read_yaml(path.read_text(encoding="utf-8"), str(path)))
    changed = 0
    tasks = []
    for task in data.tasks:
        try:
            best = optimal_steps(appliance, task)
        except (GoalError, Unreachable) as exc:
            raise FillError(f"{appliance.id} {task.id}: {exc}") from exc
        changed += best != task.optimal_steps
        tasks.append(task.model_copy(update={"optimal_steps": best}))
    if changed:
        payload = {
            "appliance": data.appliance,
            "tasks": [t.model_dump(mode="json", exclude_defaults=True) for t in tasks],
        }
        path.write_text(dump_yaml(payload), encoding="utf-8")
        appliance.tasks = tasks
    return changed
