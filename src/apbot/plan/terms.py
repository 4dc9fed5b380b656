"""What the model's structure says about a goal variable, for the terms of the lower bound
(:mod:`apbot.plan.bounds`): the entry press in front of its steps and what that press sets,
the presses that choose a programme again, the resets another variable's changes make, and
the steps that can assign a programme each value. None of these depend on the state, so the
bound works them out once per goal.
"""

from __future__ import annotations

from typing import Any

from apbot.plan.distances import INF, backwards, value_graph
from apbot.sim.compiled import CLEAR, DIGIT, TABLE, CompiledModel, leaves


def entry_requirements(
    compiled: CompiledModel, v: int, goal_vars: set[int]
) -> tuple[frozenset[int], frozenset[str], frozenset[int]] | None:
    """When every step adjusting ``v`` sits behind a step that adjusts no goal variable:
    the pointer positions from which no such entry press is needed, the features involved,
    and the steps in front (an entry press lands on one of them: presses landing on disjoint
    sets of steps are distinct presses). None when some step adjusting ``v`` can be entered
    directly."""
    if any(step.variable == v for step in compiled.anywhere_steps):
        return None  # an anywhere key adjusts it without entering anything
    free: set[int] = set()
    features: set[str] = set()
    gates: set[int] = set()
    for sid, step in enumerate(compiled.steps):
        if step.variable != v:
            continue
        if step.index == 0:
            return None
        # the steps from which one of its actions moves the pointer straight there: the one
        # before it, and those before optional steps in between
        before = [
            p
            for p in range(len(compiled.steps))
            if p != sid and any(compiled.targets[p + 1][a] == sid for a in step.actions)
        ]
        if any(compiled.steps[p].variable in goal_vars for p in before):
            return None
        free.add(sid)
        free.update(before)
        gates.update(before)
        features.add(step.feature)
    if not features:
        return None
    return frozenset(free), frozenset(features), frozenset(gates)


def gate_floor(
    compiled: CompiledModel,
    v: int,
    entry: tuple[frozenset[int], frozenset[str], frozenset[int]] | None,
    goal_value: Any,
) -> float:
    """The fewest presses of v's own steps that bring ``v`` to ``goal_value`` from where a
    press onto one of the steps in front of them (``entry``'s gates) leaves it, when every
    such press sets ``v`` to a constant (a TIME key that shows 7:00 before the dial turns).
    A route that ends in v's own steps makes such a press last before them, and between it
    and the goal the pointer stays in v's steps, where nothing but v's own keys moves v or its
    programme: it goes on from the constant, not from v's value now. 0 (no floor) when
    some gate leaves ``v`` as it is, when an anywhere key or a cycle's end may change ``v``
    or its programme between that press and v's steps, or when a key enters v's steps
    from no feature."""
    if entry is None:
        return 0.0
    _, _, gates = entry
    var = compiled.vars[v]
    watched = {v, var.parent} if var.parent >= 0 else {v}
    if any(
        step.variable in watched or any(t in watched for t, _ in step.side)
        for step in compiled.anywhere_steps
    ) or any(any(t in watched for t, _ in cycle.side) for cycle in compiled.cycles):
        return 0.0
    own = [s for s, step in enumerate(compiled.steps) if step.variable == v]
    if any(compiled.targets[0][a] in own for s in own for a in compiled.steps[s].actions):
        return 0.0
    if any(t == var.parent for s in own for t, _ in compiled.steps[s].side):
        return 0.0  # its own steps change its programme
    floor = INF
    for gate in gates:
        step = compiled.steps[gate]
        if step.variable == var.parent and var.parent >= 0:
            return 0.0
        tables = [tables for t, tables in step.side if t == v]
        if not tables:
            return 0.0  # this press leaves v as it was
        for case, domain in enumerate(var.domains):
            table = tables[-1][case]
            if domain is None or table is None:
                continue
            if len(set(table)) != 1:
                return 0.0  # not a constant: where it lands depends on v
            reverse, typed, _, _ = value_graph(compiled, v, case)
            dist = backwards(reverse, goal_value) if goal_value in domain.index else {}
            typing = min((cost + dist.get(to, INF) for to, cost in typed), default=INF)
            floor = min(floor, dist.get(domain.values[table[0]], INF), typing)
    return 0.0 if floor == INF else floor


def return_cost(compiled: CompiledModel, p: int, wanted: int) -> float:
    """Fewest presses of p's own keys that choose p again and leave it at value ``wanted``
    (from ``wanted``): a way round its values, or one press that assigns without changing
    (a go-to key, a clear, a digit)."""
    domain = compiled.vars[p].domains[0]
    assert domain is not None
    reverse, _, _, _ = value_graph(compiled, p)
    dist = backwards(reverse, domain.values[wanted])
    best = INF
    for step in compiled.all_steps:
        if step.variable != p:
            continue
        for effect in leaves(step.effects.values()):
            if effect[0] in (CLEAR, DIGIT):
                return 1.0
            if effect[0] != TABLE or effect[1][0] is None:
                continue
            after = effect[1][0][wanted]
            if after == wanted:
                if effect[2]:
                    return 1.0
                continue
            best = min(best, 1 + dist.get(domain.values[after], INF))
    return best


MUST = -3  # in place of a goal index: the variable is no goal, but must change (see below)


def reset_landings(
    compiled: CompiledModel, candidates: list[tuple[int, int]], v: int
) -> list[tuple[int, int, list[tuple[int, int]]]]:
    """Variables every change of which resets goal variable ``v``: (w, w's goal index or
    :data:`MUST`, the (case, value index) pairs the reset can leave ``v`` at).

    ``candidates`` are (w, goal index) for goal variables, (w, MUST) for programmes of goal
    settings that are no goal themselves. While a goal w is off its goal — or a MUST w has a
    setting that cannot reach its goal without w changing — w must still change, and whatever
    changes it resets v in the same press; after the last such press v still has to go from
    where the reset left it to its goal, by presses counted in v's term only. Resets are
    ``reset``/``set`` side effects of every step that can change w (w selecting no programme of
    its own, else a programme change could move it without them), or, for a setting of w,
    the programme's default every change of w restores (not for a ``remember`` setting).
    """
    found = []
    parent = compiled.vars[v].parent
    for w, wanted in candidates:
        if w == v:
            continue
        changing = [
            step
            for step in compiled.all_steps
            if step.variable == w or any(target == w for target, _ in step.side)
        ]
        landed: set[tuple[int, int]] = set()
        if parent == w:
            if wanted != MUST or v in compiled.memory_slots:
                continue  # a goal programme: the goal's case says it already
            for case, domain in enumerate(compiled.vars[v].domains):
                landed.add((-1, 0) if domain is None else (case, domain.initial))
            for step in changing:  # a side effect of the same press may move it on
                for target, assigned in step.side:
                    if target == v:
                        landed.update(_side_landings(assigned))
            found.append((w, wanted, sorted(landed)))
            continue
        if compiled.vars[w].parent >= 0:
            continue
        for step in changing:
            tables = [assigned for target, assigned in step.side if target == v]
            if not tables or (
                parent >= 0  # the same press choosing v's programme restores its default
                and (step.variable == parent or any(t == parent for t, _ in step.side))
            ):
                break
            landed.update(_side_landings(tables[-1]))  # the last assignment wins
        else:
            if changing and landed:
                if parent >= 0:
                    landed.add((-1, 0))  # a programme change may also leave it absent
                found.append((w, wanted, sorted(landed)))
    return found


def _side_landings(tables: tuple[tuple[int, ...] | None, ...]) -> set[tuple[int, int]]:
    """The (case, value index) pairs a side effect's per-case tables can assign."""
    landed: set[tuple[int, int]] = set()
    for case, table in enumerate(tables):
        if table is None:
            landed.add((-1, 0))
        else:
            landed.update((case, index) for index in set(table))
    return landed


def assigning_steps(compiled: CompiledModel, programme: int) -> list[set[int]]:
    """Per value of a programme, the steps whose actions can assign it that value (by their
    main effect or a side effect) — a superset is safe, a missing step is not."""
    var = compiled.vars[programme]
    domain = var.domains[0]
    assert domain is not None
    steps: list[set[int]] = [set() for _ in domain.values]
    for sid, step in enumerate(compiled.all_steps):  # ids past the features' are anywhere keys
        if step.variable == programme:
            for effect in leaves(step.effects.values()):
                if effect[0] in (TABLE, CLEAR) and effect[1][0] is not None:
                    for value in set(effect[1][0]):
                        steps[value].add(sid)
                elif effect[0] == DIGIT:
                    for chosen in steps:
                        chosen.add(sid)
        for target, tables in step.side:
            if target == programme and tables[0] is not None:
                steps[tables[0][0]].add(sid)
    return steps
