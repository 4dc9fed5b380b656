"""Brute-force breadth-first search over the full simulator: the reference the planner is
proved against on small models. Exponential; only for tests, benchmarks and tiny models.

The searches share nothing with the planner's reasoning (no bound, no visits) except, on
request, one exact reduction — :func:`goal_projection`, itself checked against the plain
search. The checks below them hold the planner, its bound and the suite's stored optimal counts
against their answers.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Hashable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from apbot.plan.goals import CompiledGoal
from apbot.sim.checks import guard_key
from apbot.sim.compiled import CompiledModel, State

INF = float("inf")


class BfsBudgetExceeded(RuntimeError):
    """Breadth-first search saw more states than it was allowed: the case is too large to
    brute-force, which says nothing about the planner."""


def shortest_plan_length(
    compiled: CompiledModel,
    start: State,
    goal: Mapping[str, Any],
    max_states: int = 2_000_000,
    project: bool = False,
) -> int | None:
    """Length of the shortest action sequence reaching ``goal`` (canonical values), or None
    when it is unreachable. Raises :class:`BfsBudgetExceeded` past ``max_states`` states.
    ``project`` searches states up to :func:`goal_projection` (same answer, fewer states)."""
    return _search(compiled, start, goal, max_states, project)[0]


def goal_projection(compiled: CompiledModel, goal: CompiledGoal) -> Callable[[State], Hashable]:
    """A state reduced to what can influence reaching ``goal``: the goal's variables, those
    guards read, the programmes selecting their domains and the variables conditional effects
    on them read (closed under both), the feature pointer, and the keypad buffer while it
    types one of those variables.

    Exact: an action's effect on these depends only on these (guards read guard variables,
    effects and side effects read their own variable and its programme, the pointer moves by
    itself, a buffer feeds only its step's variable), so two states with the same projection
    reach the goal in the same number of actions.
    """
    kept = set(goal.variables)
    for guard in compiled.guards:
        kept.update(v for v, _ in guard.conditions)
    return guard_key(compiled, kept)  # the same reduction, closed the same way


def _search(
    compiled: CompiledModel,
    start: State,
    goal: Mapping[str, Any],
    max_states: int,
    project: bool = False,
) -> tuple[int | None, int]:
    """(shortest length or None, states seen)."""
    target = CompiledGoal.build(compiled, goal)
    if target.holds(compiled, start):
        return 0, 1
    key: Callable[[State], Hashable] = goal_projection(compiled, target) if project else _same
    seen = {key(start)}
    frontier = [start]
    actions = range(len(compiled.action_names))
    apply = compiled.apply
    depth = 0
    while frontier:  # one layer at a time
        depth += 1
        layer = []
        for state in frontier:
            for action in actions:
                after = apply(state, action)
                if after is None:
                    continue
                k = key(after)
                if k in seen:
                    continue
                if target.holds(compiled, after):
                    return depth, len(seen) + 1
                seen.add(k)
                if len(seen) > max_states:
                    raise BfsBudgetExceeded(f"BFS gave up after {max_states} states")
                layer.append(after)
        frontier = layer
    return None, len(seen)


def _same(state: State) -> Hashable:
    return state


def reachable_graph(
    compiled: CompiledModel, start: State, max_states: int
) -> dict[State, list[State]]:
    """Every state reachable from ``start``, each with its predecessors (one entry per action
    leading to it). Raises :class:`BfsBudgetExceeded` past ``max_states`` states."""
    predecessors: dict[State, list[State]] = {start: []}
    queue: deque[State] = deque([start])
    actions = range(len(compiled.action_names))
    while queue:
        state = queue.popleft()
        for action in actions:
            after = compiled.apply(state, action)
            if after is None:
                continue
            known = predecessors.get(after)
            if known is None:
                if len(predecessors) >= max_states:
                    raise BfsBudgetExceeded(f"more than {max_states} reachable states")
                predecessors[after] = [state]
                queue.append(after)
            else:
                known.append(state)
    return predecessors


def distances_to_goal(
    compiled: CompiledModel,
    goal: Mapping[str, Any],
    start: State | None = None,
    max_states: int = 200_000,
) -> tuple[list[State], dict[State, int]]:
    """Every state reachable from ``start`` (default: the initial state), and the true number
    of actions from each to the nearest goal state (states that cannot reach it are absent).

    One forward search collects the states, one backward search from all goal states at once
    gives every distance: the ground truth a lower bound is checked against on every state.
    """
    target = CompiledGoal.build(compiled, goal)
    graph = reachable_graph(
        compiled, start if start is not None else compiled.initial_state(), max_states
    )
    distance = {state: 0 for state in graph if target.holds(compiled, state)}
    queue: deque[State] = deque(distance)
    while queue:
        state = queue.popleft()
        for previous in graph[state]:
            if previous not in distance:
                distance[previous] = distance[state] + 1
                queue.append(previous)
    return list(graph), distance


def bound_violations(
    compiled: CompiledModel,
    goal: Mapping[str, Any],
    states: Iterable[State],
    distance: Mapping[State, int],
) -> list[tuple[State, float, float]]:
    """(state, bound, true distance) wherever the planner's lower bound is not admissible:
    above the distance (infinite where the goal is unreachable), or not 0 at a goal state.

    The bound is taken as at the search's start (a half-typed buffer may be continued), the
    weakest claim that holds from every state a plan can start in.
    """
    from apbot.plan.bounds import LowerBound

    bound = LowerBound(compiled, CompiledGoal.build(compiled, goal))
    found = []
    for state in states:
        estimate = bound(state, continuing=True)
        truth = distance.get(state, INF)
        if estimate > truth or (truth == 0 and estimate != 0):
            found.append((state, estimate, truth))
    return found


def planner_mismatches(
    compiled: CompiledModel,
    goal: Mapping[str, Any],
    starts: Iterable[State],
    distance: Mapping[State, int],
) -> list[tuple[State, int | None, int | None]]:
    """(start, planner length, BFS length) wherever the planner's plan from ``start`` is not
    exactly as short as the true distance (None: unreachable, for either)."""
    from apbot.plan.plan import Unreachable, plan

    found = []
    for start in starts:
        try:
            length: int | None = len(plan(compiled, start, goal))
        except Unreachable:
            length = None
        if length != distance.get(start):
            found.append((start, length, distance.get(start)))
    return found


@dataclass(frozen=True)
class OptimalCount:
    """A stored optimal action count against breadth-first search from the initial state.

    ``shortest`` is BFS's answer (None: unreachable, or not known when ``over_budget``);
    ``states`` how many states it saw."""

    stored: int | None
    shortest: int | None
    over_budget: bool
    states: int

    @property
    def confirmed(self) -> bool:
        return not self.over_budget and self.stored is not None and self.stored == self.shortest

    @property
    def mismatch(self) -> bool:
        return not self.over_budget and not self.confirmed


def check_optimal_count(
    model: Any, goal: Mapping[str, Any], stored: int | None, max_states: int
) -> OptimalCount:
    """Is ``stored`` the true optimum for ``goal`` from the initial state? BFS over the whole
    simulator (states up to :func:`goal_projection`) decides, unless it would see more than
    ``max_states`` states."""
    from apbot.model.goal import parse_goal
    from apbot.sim.compiled import compiled_model

    compiled = compiled_model(model)
    canonical = parse_goal(compiled.model, goal)
    try:
        shortest, states = _search(
            compiled, compiled.initial_state(), canonical, max_states, project=True
        )
    except BfsBudgetExceeded:
        return OptimalCount(stored, None, True, max_states)
    return OptimalCount(stored, shortest, False, states)


def optimal_counts_line(checks: Sequence[OptimalCount]) -> str:
    """The one-line summary the stored-count check prints."""
    checked = [c for c in checks if not c.over_budget]
    confirmed = sum(c.confirmed for c in checked)
    return (
        f"optimal counts: {len(checks)} tasks, {len(checked)} checked by BFS "
        f"({len(checks) - len(checked)} over budget), {confirmed} confirmed, "
        f"{len(checked) - confirmed} mismatches"
    )


def random_walk(compiled: CompiledModel, rng: Any, steps: int) -> State:
    """A state reached by ``steps`` random accepted actions from the initial state."""
    state = compiled.initial_state()
    for _ in range(steps):
        action = rng.randrange(len(compiled.action_names))
        state = compiled.apply(state, action) or state
    return state


def compare_with_bfs(
    model: Any, goal: Mapping[str, Any], start: State | None = None, max_states: int = 200_000
) -> tuple[int | None, int | None]:
    """(planner length, BFS length) for one goal from ``start`` (default: the initial state);
    None = unreachable. Raises :class:`BfsBudgetExceeded` when BFS does not fit."""
    from apbot.model.goal import parse_goal
    from apbot.plan.plan import Unreachable, plan
    from apbot.sim.compiled import compiled_model

    compiled = compiled_model(model)
    canonical = parse_goal(compiled.model, goal)
    start = start if start is not None else compiled.initial_state()
    reference = shortest_plan_length(compiled, start, canonical, max_states)
    try:
        found: int | None = len(plan(compiled, start, canonical))
    except Unreachable:
        found = None
    return found, reference
