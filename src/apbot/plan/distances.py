"""Fewest presses over the graph of one variable's values: the per-variable distances the
lower bound (:mod:`apbot.plan.bounds`) adds up.

The graph's edges are the actions whose main variable it is (one press each); typing on its
own keypad and *jumps* from outside its steps (side effects, programme changes) reach values
from anywhere. Distances are searched backwards from the goal value, so one search serves
every state.
"""

from __future__ import annotations

from collections import deque
from typing import Any

from apbot.model.effects import typed_lengths
from apbot.sim.compiled import CLEAR, DIGIT, TABLE, CompiledModel, leaves

INF = float("inf")
ABSENT = ("absent",)  # a dependent setting that does not exist in the current programme


def value_graph(
    compiled: CompiledModel, v: int, only_case: int | None = None, reset_costs: tuple[int, ...] = ()
) -> tuple[
    dict[Any, list[tuple[Any, int]]],
    list[tuple[Any, int]],
    list[tuple[Any, int]],
    list[tuple[Any, int]],
]:
    """Reverse edges ``to -> [(from, cost)]`` over canonical values, and two kinds of "from
    anywhere" edges: typing on the variable's own keypad step, and *jumps* made from outside
    its steps (side effects, programme changes) that need no press entering them. The last
    list holds the jumps that are programme changes (also among the jumps).

    ``only_case`` keeps a programme-dependent setting inside one programme's domain (the goal's).
    ``reset_costs`` is what a programme change to each programme value, restoring the setting's
    default there, costs it (1 where this setting is the one charged for its programme's
    presses, see :class:`LowerBound`; empty: 0 everywhere).
    """
    var = compiled.vars[v]

    def cases() -> list[tuple[int, Any]]:
        return [
            (c, d)
            for c, d in enumerate(var.domains)
            if d is not None and (only_case is None or c == only_case)
        ]

    reverse: dict[Any, list[tuple[Any, int]]] = {}
    typed_anywhere: list[tuple[Any, int]] = []
    jumps: list[tuple[Any, int]] = []
    entry = getattr(var.spec, "entry", None)

    def edge(a: Any, b: Any, cost: int) -> None:
        if a != b:
            reverse.setdefault(b, []).append((a, cost))

    for step in compiled.all_steps:  # features' steps and anywhere keys alike
        if step.variable == v:
            typed = False
            for effect in leaves(step.effects.values()):
                if effect[0] in (TABLE, CLEAR):
                    for case, domain in cases():
                        table = effect[1][case]
                        if table is None:
                            continue
                        for i, j in enumerate(table):
                            edge(domain.values[i], domain.values[j], 1)
                elif effect[0] == DIGIT and entry is not None and not typed:
                    typed = True  # every digit key of the step offers the same values
                    allowed = {value for _, d in cases() for value in d.values}
                    typed_anywhere.extend(
                        item for item in typeable_values(compiled, v) if item[0] in allowed
                    )
        for target, tables in step.side:
            if target == v:
                for case, domain in cases():
                    table = tables[case]
                    if table is not None:
                        jumps.append((domain.values[table[0]], 0))
    programme: list[tuple[Any, int]] = []
    if var.parent >= 0:  # a programme change restores the new programme's default
        # ... or, for a ``remember`` setting, the value kept for it: any of its values
        remembered = v in compiled.memory_slots

        def landing(d: Any) -> list[Any]:
            return list(d.values) if remembered else [d.values[d.initial]]

        if only_case is None:
            for case, d in enumerate(var.domains):
                cost = reset_costs[case] if reset_costs else 0
                if d is None:
                    programme.append((ABSENT, cost))
                else:
                    programme.extend((value, cost) for value in landing(d))
        else:
            programme.extend((value, 0) for _, d in cases() for value in landing(d))
    return reverse, typed_anywhere, jumps + programme, programme


def typeable_values(compiled: CompiledModel, v: int) -> list[tuple[Any, int]]:
    """(value, digits needed from a fresh buffer) for every value a keypad can type."""
    cache = compiled.cache.setdefault("typeable", {})
    if v not in cache:
        var = compiled.vars[v]
        entry = getattr(var.spec, "entry", None)
        found: dict[Any, int] = {}
        for domain in var.domains:
            if entry is None or domain is None or domain.magnitudes is None:
                continue
            lengths = typed_lengths(domain.magnitudes, entry)
            for value, length in zip(domain.values, lengths, strict=True):
                if length is not None:
                    found[value] = length
        cache[v] = list(found.items())
    return cache[v]


def distances_to(
    compiled: CompiledModel,
    v: int,
    goal_value: Any,
    only_case: int | None = None,
    reset_costs: tuple[int, ...] = (),
) -> tuple[dict[Any, float], float]:
    """Fewest main actions from each value to ``goal_value``, and the cost from anywhere."""
    dist, from_anywhere, _ = distances(compiled, v, goal_value, only_case, reset_costs)
    return dist, from_anywhere


def distances(
    compiled: CompiledModel,
    v: int,
    goal_value: Any,
    only_case: int | None,
    reset_costs: tuple[int, ...],
) -> tuple[dict[Any, float], float, float]:
    """:func:`distances_to`, plus the cheapest jump landing on the goal value: the only way
    there that uses none of the variable's own steps."""
    dist, from_anywhere, jump, _ = distances_apart(compiled, v, goal_value, only_case, reset_costs)
    return dist, from_anywhere, jump


def distances_apart(
    compiled: CompiledModel,
    v: int,
    goal_value: Any,
    only_case: int | None,
    reset_costs: tuple[int, ...],
) -> tuple[dict[Any, float], float, float, float]:
    """:func:`distances`, plus the cost from anywhere by routes with no programme change."""
    reverse, typed_anywhere, jumps, programme = value_graph(compiled, v, only_case, reset_costs)
    dist = backwards(reverse, goal_value)
    anywhere = typed_anywhere + jumps
    from_anywhere = min((cost + dist.get(target, INF) for target, cost in anywhere), default=INF)
    jump = min((cost for target, cost in jumps if target == goal_value), default=INF)
    side = jumps[: len(jumps) - len(programme)]  # the programme changes come last
    unchosen = min(
        (cost + dist.get(target, INF) for target, cost in typed_anywhere + side), default=INF
    )
    return dist, from_anywhere, jump, unchosen


def per_case_table(
    compiled: CompiledModel, v: int, goal_value: Any, reset_costs: tuple[int, ...]
) -> tuple[tuple[tuple[float, ...], ...], float, float, tuple[tuple[float, ...], ...]]:
    """The bound per case and value, the bound when absent, the cheapest jump, and the bound
    per case and value with no programme change (typing and side effects only), for a
    setting of a programme the goal does not name: distances within each programme's own
    domain (with its own keys' tables), since every programme change puts the setting back to
    the new programme's default (or what it kept there). Mixing the programmes' tables in one
    graph would let a setting land on a programme's default and walk on with another's keys.
    """
    var = compiled.vars[v]
    _, typed, jumps, programme = value_graph(compiled, v, None, reset_costs)
    side = jumps[: len(jumps) - len(programme)]  # the programme changes come last
    dists: list[dict[Any, float]] = []
    for case, domain in enumerate(var.domains):
        if domain is None or goal_value not in domain.index:
            dists.append({})  # the goal cannot hold in this programme
        else:
            dists.append(backwards(value_graph(compiled, v, case)[0], goal_value))

    def from_any_case(value: Any) -> float:
        return min((dist.get(value, INF) for dist in dists), default=INF)

    anywhere = min((cost + from_any_case(target) for target, cost in typed + side), default=INF)
    remembered = v in compiled.memory_slots
    for case, domain in enumerate(var.domains):
        if domain is None:
            continue
        cost = reset_costs[case] if reset_costs else 0
        landing = domain.values if remembered else [domain.values[domain.initial]]
        anywhere = min(anywhere, cost + min(dists[case].get(value, INF) for value in landing))
    jump: float = min((cost for target, cost in jumps if target == goal_value), default=INF)
    per_case = tuple(
        ()
        if domain is None
        else tuple(min(dists[case].get(value, INF), anywhere) for value in domain.values)
        for case, domain in enumerate(var.domains)
    )
    # with no programme change: own keys within the programme, side effects, typing
    unchosen = min((cost + from_any_case(target) for target, cost in typed + side), default=INF)
    free = tuple(
        ()
        if domain is None
        else tuple(min(dists[case].get(value, INF), unchosen) for value in domain.values)
        for case, domain in enumerate(var.domains)
    )
    return per_case, anywhere, jump, free


def backwards(reverse: dict[Any, list[tuple[Any, int]]], goal_value: Any) -> dict[Any, float]:
    """Fewest counted edges from every value to ``goal_value`` (0-1 BFS backwards)."""
    dist: dict[Any, float] = {goal_value: 0}
    queue: deque[Any] = deque([goal_value])
    while queue:
        node = queue.popleft()
        for source, cost in reverse.get(node, []):
            candidate = dist[node] + cost
            if candidate < dist.get(source, INF):
                dist[source] = candidate
                (queue.appendleft if cost == 0 else queue.append)(source)
    return dist
