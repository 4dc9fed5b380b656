"""Does a task's goal pin down the operation its instruction asks for?

A benchmark judges success on the final state, so a goal that an obviously different operation
also meets scores that operation a success (a microwave running a one-minute express cook
passes a "time defrost for 8:30" goal that says only ``running=on``). These checks look for
such goals on the ground-truth model, by planning and simulating, never by reading the text:

``quick-start``
    After the goal's settings are made, one press (possibly after a press that changes no
    value, such as a START that confirms a clock) meets the whole goal and itself changes a
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
from apbot.model.schema import ApplianceModel
from apbot.plan.goals import CompiledGoal
from apbot.plan.plan import Plan, PlannedAction, Unreachable, plan
from apbot.sim.compiled import CompiledModel, State, compiled_model

# The variables that say an appliance is operating (the suite's naming convention).
RUN_VARIABLES = frozenset({"running", "heating", "dispensing", "status"})
CHECKS = ("quick-start", "start-only", "free")


@dataclass(frozen=True)
class GoalFinding:
    """One way the goal can be met by a different operation; ``key`` is what ``allow`` names."""

    key: str
    message: str


def goal_findings(
    model: ApplianceModel | CompiledModel, goal: Goal, oracle: Plan | None = None
) -> list[GoalFinding]:
    """Every finding for a canonical, reachable goal on the ground-truth ``model``.

    ``oracle`` is the goal's shortest plan when the caller has it already (it is not re-done).
    """
    plans = _Plans(compiled_model(model))
    if oracle is not None:
        plans.seed(goal, oracle)
    final = plans.final(goal)
    if final is None:
        return []
    findings = list(_quick_start(plans, goal, final))
    findings += _start_only(plans, goal)
    findings += _free(plans, goal)
    return findings


class _Plans:
    """Shortest plans from the initial state; each goal is planned once (the checks share)."""

    def __init__(self, compiled: CompiledModel) -> None:
        self.compiled = compiled
        self.start = compiled.initial_state()
        self._plans: dict[frozenset[tuple[str, Any]], Plan | None] = {}
        self._finals: dict[frozenset[tuple[str, Any]], State | None] = {}

    def seed(self, goal: Mapping[str, Any], found: Plan) -> None:
        """Remember a plan for ``goal`` found elsewhere."""
        self._plans[frozenset(goal.items())] = found

    def plan(self, goal: Mapping[str, Any]) -> Plan | None:
        """The shortest plan for ``goal`` (None: unreachable)."""
        key = frozenset(goal.items())
        if key not in self._plans:
            try:
                self._plans[key] = plan(self.compiled, self.start, goal)
            except Unreachable:
                self._plans[key] = None
        return self._plans[key]

    def final(self, goal: Mapping[str, Any]) -> State | None:
        """Where the shortest plan for ``goal`` leaves the appliance (None: unreachable)."""
        key = frozenset(goal.items())
        if key not in self._finals:
            found = self.plan(goal)
            state: State | None = None
            if found is not None:
                state = self.start
                for action in found.actions:
                    state = self.apply(state, action)
            self._finals[key] = state
        return self._finals[key]

    def apply(self, state: State, action: PlannedAction) -> State:
        index = self.compiled.action_index[action.name]
        after = self.compiled.apply(state, index, action.seconds)
        assert after is not None, "a verified plan was refused"
        return after


def _split(goal: Goal) -> tuple[Goal, Goal]:
    """(running variables, settings) of a goal."""
    running = {k: v for k, v in goal.items() if k in RUN_VARIABLES}
    return running, {k: v for k, v in goal.items() if k not in running}


def _quick_start(plans: _Plans, goal: Goal, final: State) -> Iterator[GoalFinding]:
    """A press after the settings that meets the goal and itself changes another setting.

    The press may follow one press that changes no value (a START that confirms a clock, a
    key that leaves a menu), as an agent confused about the panel would press it.
    """
    running, settings = _split(goal)
    if not running:
        return
    compiled = plans.compiled
    made = plans.final(settings) if settings else plans.start
    target = CompiledGoal.build(compiled, goal)
    if made is None or target.holds(compiled, made):
        return  # unreachable, or nothing left to start ("don't start it yet")
    others = [v for v, var in enumerate(compiled.vars) if var.name not in goal]
    frontier: list[tuple[State, tuple[str, ...]]] = [(made, ())]
    for _depth in range(2):
        following = []
        for state, presses in frontier:
            for action, name in enumerate(compiled.action_names):
                after = compiled.apply(state, action)
                if after is None:
                    continue
                path = (*presses, name)
                if after.values == state.values:
                    following.append((after, path))
                    continue
                changed = [
                    v
                    for v in others
                    if after.values[v] != state.values[v] and after.values[v] != final.values[v]
                ]
                if changed and target.holds(compiled, after):
                    names = [compiled.vars[v].name for v in changed]
                    yield GoalFinding(
                        "quick-start",
                        f"after the settings, {' + '.join(path)} meets the goal and sets "
                        f"{_shown({n: compiled.value(after, n) for n in names})} (the oracle "
                        f"leaves {_shown({n: compiled.value(final, n) for n in names})}): "
                        "a different operation",
                    )
                    return
        frontier = following


def _start_only(plans: _Plans, goal: Goal) -> Iterator[GoalFinding]:
    """The plan for the running variables alone meets the goal, its settings untouched.

    A setting that plan changes on the way counts only when the macro action that starts the
    appliance changes it (a quick-start key); one the plan must select first (a programme
    before START) is a real constraint.
    """
    running, settings = _split(goal)
    found = plans.plan(running) if running and settings else None
    if found is None:
        return
    compiled = plans.compiled
    state = plans.start
    changed_by: dict[str, int] = {}
    for index, macro in enumerate(found.macro_actions):
        for action in macro.actions:
            before, state = state, plans.apply(state, action)
            for name in goal:
                if compiled.value(state, name) != compiled.value(before, name):
                    changed_by[name] = index
    if not CompiledGoal.build(compiled, goal).holds(compiled, state):
        return
    starter = max((changed_by[n] for n in running if n in changed_by), default=-1)
    if all(changed_by.get(name, starter) == starter for name in settings):
        yield GoalFinding(
            "start-only",
            f"a plan for {_shown(running)} alone already meets the goal: "
            "its settings are defaults or set by the starting key",
        )


def _free(plans: _Plans, goal: Goal) -> Iterator[GoalFinding]:
    """A goal value that is the default and that a plan for the rest of the goal leaves alone.

    The default is the initial value or, for a setting that depends on a programme the goal
    names, the value selecting that programme gives it.
    """
    for name, value in goal.items():
        if _default(plans.compiled, plans.start, goal, name) != value:
            continue
        rest = {k: v for k, v in goal.items() if k != name}
        state = plans.final(rest) if rest else plans.start
        if state is not None and plans.compiled.value(state, name) == value:
            yield GoalFinding(
                f"free:{name}",
                f"{name}={value} is its default and a plan for the rest of the goal "
                "leaves it so: the goal asks nothing with it",
            )


def _default(compiled: CompiledModel, start: State, goal: Goal, name: str) -> Any:
    """The value ``name`` has before anyone touches it, once the goal's programme is chosen."""
    var = compiled.vars[compiled.var_index[name]]
    if var.parent < 0 or compiled.vars[var.parent].name not in goal:
        return compiled.value(start, name)
    parent = compiled.vars[var.parent]
    values = list(start.values)
    parent_domain = parent.domain(values)
    if parent_domain is None or goal[parent.name] not in parent_domain.index:
        return None
    values[var.parent] = parent_domain.index[goal[parent.name]]
    domain = var.domain(values)
    return None if domain is None else domain.values[domain.initial]


def _shown(values: Mapping[str, Any]) -> str:
    return ", ".join(f"{k}={v}" for k, v in values.items())
