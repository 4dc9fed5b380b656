"""``plan(model, state, goal)``: macro actions in order, each with its exact physical actions.

The plan is the shortest action sequence the model allows (see ``apbot.plan.search``), cut into
macro actions — one per feature entered — and verified by simulating it on the model before it
is returned. Each macro action carries the values it should leave on the display, which the
closed loop compares with what it observes.

>>> from apbot.examples import load_example
>>> p = plan(load_example("washing_machine"), None, {"power": "on", "programme": "wool"})
>>> [m.feature for m in p.macro_actions], len(p)
(['power', 'select_programme'], 5)
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from apbot.model.domain import marked_unreachable
from apbot.model.goal import GoalError, parse_goal
from apbot.model.schema import ApplianceModel
from apbot.plan.goals import CompiledGoal
from apbot.plan.search import DEFAULT_BUDGET, SearchExhausted, TaskSearch, Visit
from apbot.sim.compiled import CompiledModel, State
from apbot.sim.simulator import require_model

__all__ = ["GoalError", "MacroAction", "Plan", "PlannedAction", "Unreachable", "plan"]


class Unreachable(Exception):
    """The goal cannot be reached from this state; ``reason`` says why, in plain words.

    ``blocked`` names the goal variables whose goal value no action leads to at all, whatever
    the guards allow: no guard relaxed can make such a goal reachable. ``reason`` may be
    given as a function, called the first time it is read — its "it can reach …" walk costs
    more than many a failed search, and callers that only try a guess never read it.
    """

    def __init__(
        self,
        reason: str | Callable[[], str],
        budget_hit: bool = False,
        blocked: tuple[str, ...] = (),
        generated: int = 0,
    ) -> None:
        # a short message for repr and tracebacks; a reason still to be worked out stays unread
        super().__init__(reason if isinstance(reason, str) else "the goal cannot be reached")
        self._reason = reason
        self.budget_hit = budget_hit  # the search gave up: the goal may still be reachable
        self.blocked = blocked
        self.generated = generated  # search successors spent finding out

    @property
    def reason(self) -> str:
        if not isinstance(self._reason, str):
            self._reason = self._reason()
        return self._reason

    def __str__(self) -> str:
        return self.reason

    def __reduce__(self) -> tuple[Any, ...]:
        return (Unreachable, (self.reason, self.budget_hit, self.blocked, self.generated))

    def again(self) -> Unreachable:
        """A fresh exception with the same answer (its reason still unread if it was)."""
        return Unreachable(self._reason, self.budget_hit, self.blocked, self.generated)


@dataclass(frozen=True)
class PlannedAction:
    """One physical action to perform: which controls, which skill, for how long."""

    name: str
    skill: str
    controls: tuple[str, ...]
    seconds: float | None = None

    def __str__(self) -> str:
        return f"{self.name} ({self.seconds:g} s)" if self.seconds else self.name


@dataclass(frozen=True)
class MacroAction:
    """One feature's procedure as executed: the steps visited and the actions in order.

    ``expect`` holds the values the adjusted variables should show afterwards.
    """

    feature: str
    steps: tuple[int, ...]
    actions: tuple[PlannedAction, ...]
    expect: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Plan:
    """The macro actions in order. ``len(plan)`` is the number of physical actions."""

    goal: dict[str, Any]
    macro_actions: tuple[MacroAction, ...]
    expanded: int = 0
    seconds: float = 0.0
    generated: int = 0  # search successors spent finding it

    @property
    def actions(self) -> list[PlannedAction]:
        return [a for m in self.macro_actions for a in m.actions]

    def __len__(self) -> int:
        return sum(len(m.actions) for m in self.macro_actions)


def plan(
    model: ApplianceModel | CompiledModel,
    state: State | None,
    goal: Mapping[str, Any] | Iterable[str],
    budget: int = DEFAULT_BUDGET,
    work: int | None = None,
    most: int | None = None,
) -> Plan:
    """The shortest plan from ``state`` (None: the initial state) to ``goal``.

    ``goal`` maps variable names to values in any accepted notation ("30 min", "on"), or is a
    list of ``NAME=VALUE`` strings. Raises :class:`GoalError` for an invalid goal,
    :class:`Unreachable` (with the reason) when no action sequence reaches it, and a
    ``TypeError`` or ``ValueError`` naming the argument for a model, state or budget that
    is not one. ``budget`` bounds the search states expanded, ``work`` the successors
    generated (default: 20 per state of the budget); past either the search gives up with
    :class:`Unreachable` and ``budget_hit`` set. ``most`` (None: no limit) is the longest plan
    wanted: when every plan is longer, :class:`Unreachable` says so (a caller that only
    takes a plan shorter than one it has needs no search past that length).
    """
    started = time.perf_counter()
    compiled = require_model(model, "plan")
    if state is not None:
        compiled.check_state(state)
    if isinstance(goal, str | bytes) or not isinstance(goal, Mapping | Iterable):
        raise TypeError(
            "plan's goal maps variable names to values ({'power': 'on'}) or is a list of "
            f"NAME=VALUE strings (['power=on']), not {type(goal).__name__} {goal!r}"
        )
    if isinstance(budget, bool) or not isinstance(budget, int) or budget < 1:
        raise ValueError(f"budget is a positive number of search states, not {budget!r}")
    if work is not None and (isinstance(work, bool) or not isinstance(work, int) or work < 1):
        raise ValueError(f"work is a positive number of search successors, not {work!r}")
    if most is not None and (isinstance(most, bool) or not isinstance(most, int) or most < 0):
        raise ValueError(f"most is a number of actions (0 or more), not {most!r}")
    canonical = parse_goal(compiled.model, goal)
    start = state if state is not None else compiled.initial_state()
    target = CompiledGoal.build(compiled, canonical)
    search = TaskSearch(compiled, target, budget, work, most)
    try:
        result = search.run(start)
    except SearchExhausted as exc:
        blocked = () if exc.budget_hit else tuple(search.bound.blocking(start))
        raise Unreachable(
            _explainer(compiled, search, start, canonical, exc, blocked),
            exc.budget_hit,
            blocked,
            search.generated,
        ) from None
    macro_actions = _macro_actions(compiled, start, result.visits)
    found = Plan(
        canonical,
        macro_actions,
        result.expanded,
        time.perf_counter() - started,
        search.generated,
    )
    _verify(compiled, start, target, found)
    return found


def _planned(compiled: CompiledModel, action: int) -> PlannedAction:
    name = compiled.action_names[action]
    spec = compiled.model.actions[name]
    return PlannedAction(name, spec.skill, tuple(spec.control_ids), spec.seconds)


def _macro_actions(
    compiled: CompiledModel, start: State, visits: tuple[Visit, ...]
) -> tuple[MacroAction, ...]:
    """Group visits into macro actions: a new one starts whenever a feature is (re)entered."""
    groups: list[list[Visit]] = []
    previous = start.step
    for visit in visits:
        continues = (
            previous >= 0
            and not visit.free
            and (visit.step == previous or _skips_to(compiled, previous, visit.step))
        )
        if groups and continues and not groups[-1][-1].free:
            groups[-1].append(visit)
        else:
            groups.append([visit])
        previous = visit.step
    macro_actions = []
    state = start
    for group in groups:
        changed: list[int] = []
        for visit in group:
            for action in visit.actions:
                after = compiled.apply(state, action)
                assert after is not None, "planned action refused while grouping"
                state = after
            info = (
                compiled.anywhere.get(visit.actions[0])
                if visit.free
                else compiled.steps[visit.step]
            )
            if info is not None:
                if info.variable >= 0:
                    changed.append(info.variable)
                changed.extend(v for v, _ in info.side)
        expect = {
            compiled.vars[v].name: compiled.value(state, compiled.vars[v].name)
            for v in dict.fromkeys(changed)
        }
        if group[0].free:  # an anywhere key or a wait is a macro action of its own
            name = compiled.action_names[group[0].actions[0]]
            feature = "wait" if compiled.model.actions[name].skill == "wait" else "anywhere"
            indices: tuple[int, ...] = ()
        else:
            feature = compiled.steps[group[0].step].feature
            indices = tuple(compiled.steps[v.step].index for v in group)
        macro_actions.append(
            MacroAction(
                feature,
                indices,
                tuple(_planned(compiled, a) for v in group for a in v.actions),
                expect,
            )
        )
    return tuple(macro_actions)


def _skips_to(compiled: CompiledModel, step: int, later: int) -> bool:
    """Whether ``later`` follows ``step`` in its feature, past optional steps only."""
    following = compiled.steps[step].next_step
    while following >= 0:
        if following == later:
            return True
        following = (
            compiled.steps[following].next_step if compiled.steps[following].optional else -1
        )
    return False


def _verify(compiled: CompiledModel, start: State, goal: CompiledGoal, found: Plan) -> None:
    """Simulate the plan on the model: every action accepted, the goal holds at the end."""
    state = start
    for action in found.actions:
        after = compiled.apply(state, compiled.action_index[action.name], action.seconds)
        if after is None:
            raise AssertionError(f"planner bug: {action.name} is refused by the model")
        state = after
    if not goal.holds(compiled, state):
        raise AssertionError("planner bug: the plan does not reach the goal on the model")


def _explainer(
    compiled: CompiledModel,
    search: TaskSearch,
    start: State,
    goal: dict[str, Any],
    exc: SearchExhausted,
    blocked: tuple[str, ...],
) -> str | Callable[[], str]:
    """Why a goal is out of reach, in terms of the model: at once when that is cheap, else
    as a function that works it out when asked (it holds no reference to the search)."""
    if exc.budget_hit:
        return (
            f"gave up after expanding {exc.expanded} search states (budget {search.budget}"
            f" states, {search.work} successors); the goal may be reachable but is too costly"
            " to plan — raise the budget"
        )
    most, expanded = search.most, exc.expanded
    return lambda: _explain(compiled, start, goal, blocked, most, expanded)


def _explain(
    compiled: CompiledModel,
    start: State,
    goal: dict[str, Any],
    blocked: tuple[str, ...],
    most: int | None,
    expanded: int,
) -> str:
    """Why a goal is out of reach (the search ran out, not its budget)."""
    declared = [
        f"{name} cannot become {goal[name]!r}: the model declares it unreachable "
        f"(variables.{name}.unreachable: the appliance sets it itself, no key does)"
        for name in goal
        if goal[name] in marked_unreachable(compiled.model.variables[name])
        and goal[name] not in _forward_values(compiled, start, compiled.var_index[name])
    ]
    if declared:
        return "; ".join(declared)
    if blocked:
        parts = []
        for name in blocked:
            current = compiled.value(start, name)
            reach = _forward_values(compiled, start, compiled.var_index[name])
            shown = ", ".join(str(v) for v in reach[:8]) + (", ..." if len(reach) > 8 else "")
            parts.append(
                f"{name} cannot become {goal[name]!r} from {current!r}: no action of "
                f"the model leads there (it can reach {shown})"
            )
        return "; ".join(parts)
    if most is not None:
        return f"no plan of at most {most} actions reaches the goal"
    names = ", ".join(f"{k}={v}" for k, v in goal.items())
    if CompiledGoal.build(compiled, goal).case_conflict(compiled):
        return (
            f"no programme lets {names} hold together: each of those settings' values exists"
            " only in some programmes, and no programme has them all"
        )
    return (
        f"no action sequence makes {names} hold together (searched {expanded} states);"
        " a guard or a programme restriction keeps them apart"
    )


def _forward_values(compiled: CompiledModel, start: State, v: int) -> list[Any]:
    """Values of variable ``v`` reachable by any sequence of actions from ``start`` (bounded)."""
    seen = {start}
    frontier = [start]
    values: dict[Any, None] = {compiled.value(start, compiled.vars[v].name): None}
    while frontier and len(seen) < 20_000:
        state = frontier.pop()
        for action in range(len(compiled.action_names)):
            after = compiled.apply(state, action)
            if after is not None and after not in seen:
                seen.add(after)
                frontier.append(after)
                values[compiled.value(after, compiled.vars[v].name)] = None
    from apbot.model.domain import all_values

    order = {value: i for i, value in enumerate(all_values(compiled.vars[v].spec))}
    return sorted(values, key=lambda value: order.get(value, len(order)))
