"""Brute-force breadth-first search over the full simulator: the reference the planner is
proved against on small models. Exponential; only for tests and tiny models."""

from __future__ import annotations

from collections import deque
from collections.abc import Mapping
from typing import Any

from apbot.plan.goals import CompiledGoal
from apbot.sim.compiled import CompiledModel, State


def shortest_plan_length(
    compiled: CompiledModel, start: State, goal: Mapping[str, Any], max_states: int = 2_000_000
) -> int | None:
    """Length of the shortest action sequence reaching ``goal`` (canonical values), or None
    when it is unreachable. Raises RuntimeError if more than ``max_states`` states are seen."""
    target = CompiledGoal.build(compiled, goal)
    if target.holds(compiled, start):
        return 0
    depth = {start: 0}
    queue: deque[State] = deque([start])
    actions = range(len(compiled.action_names))
    while queue:
        state = queue.popleft()
        for action in actions:
            after = compiled.apply(state, action)
            if after is None or after in depth:
                continue
            depth[after] = depth[state] + 1
            if target.holds(compiled, after):
                return depth[after]
            if len(depth) > max_states:
                raise RuntimeError(f"BFS gave up after {max_states} states")
            queue.append(after)
    return None


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
    None = unreachable."""
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
