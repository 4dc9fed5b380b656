"""Does a task's goal pin down the operation its instruction asks for?

A benchmark judges success on the final state, so a goal that an obviously different operation
also meets scores that operation a success (a microwave running a one-minute express cook
passes a "time defrost for 8:30" goal that says only ``running=on``). These checks look for
such goals on the ground-truth model, by planning and simulating, never by reading the text:

``quick-start``
    After the goal's settings are made, one press meets the whole goal and itself changes a
    variable outside the goal to a value the oracle does not leave: a quick-start or express
    key that starts *something else*, which the goal cannot tell apart.
``start-only``
    A plan for the goal's running variables alone (``running=on`` …) already meets the whole
    goal: the settings are at their defaults or a starting key sets them, so they ask nothing.
``free``
    A goal value is the variable's default (its initial value, or the value the goal's
    programme gives it) and a plan for the rest of the goal leaves it there: it pads the goal
    without constraining it.

A task may record why a flagged variable is wanted anyway (the instruction says "don't start
it", or names the default value on purpose) under ``allow:`` in ``tasks.yaml``, keyed by the
check and variable (``free:running``, ``start-only``, ``quick-start``); an ``allow`` entry that
no longer matches anything is itself reported, so exceptions do not outlive their reason.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any

from apbot.model.goal import Goal
from apbot.plan.goals import CompiledGoal
from apbot.plan.plan import Unreachable, plan
from apbot.sim.compiled import CompiledModel, State, compiled_model

# The variables that say an appliance is operating (the suite's naming convention).
RUN_VARIABLES = frozenset({"running", "heating", "dispensing", "status"})
CHECKS = ("quick-start", "start-only", "free")


@dataclass(frozen=True)
class GoalFinding:
    """One way the goal can be met by a different operation; ``key`` is what ``allow`` names."""

    key: str
    message: str


def goal_findings(model: Any, goal: Goal) -> list[GoalFinding]:
    """Every finding for a canonical, reachable goal on the ground-truth ``model``."""
    compiled = compiled_model(model)
    start = compiled.initial_state()
    final = _final_state(compiled, start, goal)
    if final is None:
        return []
    findings = list(_quick_start(compiled, start, goal, final))
    findings += _start_only(compiled, start, goal)
    findings += _free(compiled, start, goal)
    return findings


def _final_state(compiled: CompiledModel, start: State, goal: Mapping[str, Any]) -> State | None:
    """Where the shortest plan for ``goal`` leaves the appliance (None: unreachable)."""
    try:
        found = plan(compiled, start, goal)
    except Unreachable:
        return None
    state = start
    for action in found.actions:
        after = compiled.apply(state, compiled.action_index[action.name], action.seconds)
        assert after is not None, "a verified plan was refused"
        state = after
    return state


def _quick_start(
    compiled: CompiledModel, start: State, goal: Goal, final: State
) -> Iterator[GoalFinding]:
    """A press after the settings that meets the goal and itself changes another setting.

    The press may follow one press that changes no value (a START that confirms a clock, a
    key that leaves a menu), as an agent confused about the panel would press it.
    """
    running = {k: v for k, v in goal.items() if k in RUN_VARIABLES}
    settings = {k: v for k, v in goal.items() if k not in RUN_VARIABLES}
    if not running:
        return
    made = _final_state(compiled, start, settings) if settings else start
    if made is None:
        return
    target = CompiledGoal.build(compiled, goal)
    if target.holds(compiled, made):
        return  # nothing left to start ("don't start it yet")
    expected = compiled.assignment(final)
    frontier: list[tuple[State, tuple[str, ...]]] = [(made, ())]
    for _depth in range(2):
        following = []
        for state, presses in frontier:
            values = compiled.assignment(state)
            for action, name in enumerate(compiled.action_names):
                after = compiled.apply(state, action)
                if after is None:
                    continue
                path = (*presses, name)
                now = compiled.assignment(after)
                if now == values:
                    following.append((after, path))
                    continue
                if not target.holds(compiled, after):
                    continue
                changed = {
                    k: v
                    for k, v in now.items()
                    if k not in goal and v not in (values[k], expected[k])
                }
                if changed:
                    yield GoalFinding(
                        "quick-start",
                        f"after the settings, {' + '.join(path)} meets the goal and sets "
                        f"{_shown(changed)} (the oracle leaves "
                        f"{_shown({k: expected[k] for k in changed})}): a different operation",
                    )
                    return
        frontier = following


def _start_only(compiled: CompiledModel, start: State, goal: Goal) -> Iterator[GoalFinding]:
    """The plan for the running variables alone meets the goal, its settings untouched.

    A setting that plan changes on the way counts only when the macro action that starts the
    appliance changes it (a quick-start key); one the plan must select first (a programme
    before START) is a real constraint.
    """
    running = {k: v for k, v in goal.items() if k in RUN_VARIABLES}
    if not running or len(running) == len(goal):
        return
    try:
        found = plan(compiled, start, running)
    except Unreachable:
        return
    state = start
    changed_by: dict[str, int] = {}
    for index, macro in enumerate(found.macro_actions):
        for action in macro.actions:
            before = state
            after = compiled.apply(state, compiled.action_index[action.name], action.seconds)
            assert after is not None, "a verified plan was refused"
            state = after
            for name in goal:
                if compiled.value(after, name) != compiled.value(before, name):
                    changed_by[name] = index
    if not CompiledGoal.build(compiled, goal).holds(compiled, state):
        return
    starter = max((changed_by[n] for n in running if n in changed_by), default=-1)
    settings = [name for name in goal if name not in running]
    if all(changed_by.get(name, starter) == starter for name in settings):
        yield GoalFinding(
            "start-only",
            f"a plan for {_shown(running)} alone already meets the goal: "
            "its settings are defaults or set by the starting key",
        )


def _free(compiled: CompiledModel, start: State, goal: Goal) -> Iterator[GoalFinding]:
    """A goal value that is the default and that a plan for the rest of the goal leaves alone.

    The default is the initial value or, for a setting that depends on a programme the goal
    names, the value selecting that programme gives it.
    """
    for name, value in goal.items():
        default = _default(compiled, start, goal, name)
        if default != value:
            continue
        rest = {k: v for k, v in goal.items() if k != name}
        state = start if not rest else _final_state(compiled, start, rest)
        if state is not None and compiled.value(state, name) == value:
            yield GoalFinding(
                f"free:{name}",
                f"{name}={value} is its default and a plan for the rest of the goal "
                "leaves it so: the goal asks nothing with it",
            )


def _default(compiled: CompiledModel, start: State, goal: Goal, name: str) -> Any:
    var = compiled.vars[compiled.var_index[name]]
    if var.parent < 0:
        return compiled.value(start, name)
    parent = compiled.vars[var.parent]
    if parent.name not in goal:
        return compiled.value(start, name)
    values = list(start.values)
    parent_domain = parent.domain(values)
    if parent_domain is None or goal[parent.name] not in parent_domain.index:
        return None
    values[var.parent] = parent_domain.index[goal[parent.name]]
    domain = var.domain(values)
    return None if domain is None else domain.values[domain.initial]


def _shown(values: Mapping[str, Any]) -> str:
    return ", ".join(f"{k}={v}" for k, v in values.items())
