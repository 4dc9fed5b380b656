"""The task policy: A* over visits, from the current state to a goal, on the shortest path.

Search nodes are states projected onto the *relevant* variables — the goal's, those guards read
(power, lock, running) and the programmes that goal settings depend on — plus the feature
pointer. Nothing else influences how those variables evolve, so the projection loses nothing.
Edges are visits (``apbot.plan.visits``) and single actions that bypass the pointer (a key
from ``anywhere``, a wait letting a timeout expire); after those the step the pointer stayed on
may be continued. An edge costs its number of physical actions (ties broken towards presses
made while the display is lit).
The heuristic (``apbot.plan.bounds``) is admissible and consistent, so the first goal node
popped is optimal: the order of macro actions (power before settings, programme before its
settings, start last) falls out of the search instead of being hard-coded.

The paper's A* kept a constant path cost; ours counts every press. A node's successors (the
visits one action starts, explored once and cached) are ``apbot.plan.edges``.
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Hashable, Iterator
from dataclasses import dataclass
from operator import itemgetter
from typing import Any

from apbot.plan.abstract import out_of_reach
from apbot.plan.bounds import LowerBound
from apbot.plan.distances import INF
from apbot.plan.edges import CachedVisit, Ends, SearchExhausted, VisitEdges
from apbot.plan.goals import CompiledGoal
from apbot.plan.visits import VisitTree
from apbot.sim.compiled import DIGIT, CompiledModel, State

__all__ = ["DEFAULT_BUDGET", "SearchExhausted", "SearchResult", "TaskSearch", "Visit"]

DEFAULT_BUDGET = 200_000
# states the search may hold per state of its budget: a node with a thousand-end visit fills
# memory long before the budget of expanded nodes runs out
STORED_PER_BUDGET = 2
# successors the search may generate per state of its budget (each costs a bound evaluation)
EDGES_PER_BUDGET = 20
# Path cost is lexicographic, packed in one int: presses × PRESS + presses made while a guard
# keeps the display dark. The plan stays shortest; among equally short plans it prefers to set
# things where the display shows them, so the closed loop can check what it did.
PRESS = 1 << 16
# successors generated before the search asks a small abstraction whether the goal is out of
# reach at all (``apbot.plan.abstract``): cheap searches never pay for the question
ASK_ABSTRACTION_AFTER = 5_000
# successors each one-variable part of the goal may spend proving itself out of reach (see
# ``TaskSearch._part_out_of_reach``): a part searches a far smaller space than the whole
PART_WORK = 20_000


@dataclass(frozen=True)
class Visit:
    """One visit of the optimal plan: a step id and the actions spent there."""

    step: int
    actions: tuple[int, ...]
    free: bool = False  # one action that does not move through the pointer (anywhere, wait)


def _presses(tree: VisitTree | None, way: int | tuple[int, ...]) -> tuple[int, ...]:
    if isinstance(way, int):
        assert tree is not None
        return tree.path(way)
    return way


@dataclass(frozen=True)
class SearchResult:
    visits: tuple[Visit, ...]
    final: State
    expanded: int


def relevant_variables(compiled: CompiledModel, goal: CompiledGoal) -> list[int]:
    """Goal variables, guard variables, and the parents that select their domains."""
    relevant = set(goal.variables)
    for guard in compiled.guards:
        relevant.update(v for v, _ in guard.conditions)
    return sorted(compiled.influencers(relevant))


class TaskSearch(VisitEdges):
    """A* from one state to one goal. Build per query; cheap to construct."""

    def __init__(
        self,
        compiled: CompiledModel,
        goal: CompiledGoal,
        budget: int = DEFAULT_BUDGET,
        work: int | None = None,
        most: int | None = None,
    ) -> None:
        self.compiled = compiled
        self.goal = goal
        self.budget = budget
        # successors generated before giving up: the time a search takes, where ``budget``
        # (expanded nodes) is not — one node with a thousand-end visit costs a thousand
        self.work = EDGES_PER_BUDGET * budget if work is None else work
        # the longest plan wanted (None: any): a caller comparing with a plan it has prunes
        # every node whose bound says it cannot do as well
        self.most = most
        self._ceiling = INF if most is None else (most + 1) * PRESS - 1
        self.relevant = relevant_variables(compiled, goal)
        relevant_set = set(self.relevant)
        getter = itemgetter(*self.relevant) if self.relevant else (lambda values: ())
        self._project = getter if len(self.relevant) != 1 else (lambda vs: (getter(vs),))
        # a keypad buffer matters only while typing a relevant variable
        self.keypad_step = tuple(
            step.variable in relevant_set and any(e[0] == DIGIT for e in step.effects.values())
            for step in compiled.steps
        )
        self._memory = compiled.memory_of(self.relevant)
        self.bound = LowerBound(compiled, goal)
        self._visit_cache: dict[Hashable, CachedVisit] = {}
        self._slots: dict[int, tuple[tuple[int, ...], tuple[int, ...]]] = {}
        self._cached_ends = 0  # visit ends held by the visit cache
        self._footprints: dict[int, tuple[tuple[int, ...], tuple[int, ...]]] = {}
        self._keypad_targets: dict[int, list[float]] = {}
        # nodes reached by an anywhere key or a wait: the pointer stayed, so the step it is on
        # may be continued (a visit there is not maximal any more)
        self._continuable: set[Hashable] = set()
        self.generated = 0  # successors generated by the last run: the work it cost

    def key(self, state: State) -> Hashable:
        buffer = state.buffer if state.step >= 0 and self.keypad_step[state.step] else ""
        if self._memory:  # what remembered settings keep for other programmes
            kept = tuple(state.memory[s] for s in self._memory)
            return (self._project(state.values), state.step, buffer, kept)
        return (self._project(state.values), state.step, buffer)

    def run(self, start: State) -> SearchResult:
        compiled = self.compiled
        bound = self.bound
        h0 = bound(start, continuing=True)
        ceiling = self._ceiling
        if h0 == INF or h0 * PRESS > ceiling or self.goal.case_conflict(compiled):
            raise SearchExhausted("unreachable", 0, False)
        start_key = self.key(start)
        best = {start_key: 0}
        came_from: dict[
            Hashable, tuple[Hashable, int, VisitTree | None, int | tuple[int, ...], bool] | None
        ] = {start_key: None}
        states = {start_key: start}
        tie = itertools.count()
        frontier = [(h0 * PRESS, 0, next(tie), start_key)]
        expanded = generated = self.generated = 0
        asked = False
        while frontier:
            _, negative_cost, _, node = heapq.heappop(frontier)
            cost = -negative_cost
            if cost > best[node]:
                continue
            state = states[node]
            if self.goal.holds(compiled, state):
                return SearchResult(self._path(came_from, node), state, expanded)
            expanded += 1
            if expanded > self.budget:
                raise SearchExhausted("budget", expanded, True)
            in_the_dark = bool(compiled.guards) and compiled.hiding_guard(state) is not None
            edges = self._edges(state, node == start_key or node in self._continuable)
            generated += sum(len(e.visit[1]) if isinstance(e, Ends) else 1 for e in edges)
            self.generated = generated
            if generated > self.work:  # thousand-end visits: time runs out
                raise SearchExhausted("budget", expanded, True)
            if not asked and generated > ASK_ABSTRACTION_AFTER:
                asked = True
                if out_of_reach(compiled, self.goal, start):
                    raise SearchExhausted("unreachable", expanded, False)
                proven, spent = self._part_out_of_reach(start, self.work - generated)
                generated += spent  # the parts' searches are work done for this one
                self.generated = generated
                if proven:
                    raise SearchExhausted("unreachable", expanded, False)
            projected: list[int] | None = None
            for edge in edges:
                if isinstance(edge, Ends):  # the same as below, states built only when kept
                    if projected is None:
                        projected = list(self.key(state)[0])  # type: ignore[index]
                    if self._visit_successors(
                        edge,
                        state,
                        node,
                        cost,
                        in_the_dark,
                        projected,
                        best,
                        states,
                        came_from,
                        frontier,
                        tie,
                        expanded,
                    ):
                        raise SearchExhausted("budget", expanded, True)
                    continue
                after, presses, tree, way, free = edge
                # presses first; among plans of equal length, fewer presses with a dark display
                new_cost = cost + presses * PRESS + (presses if in_the_dark else 0)
                k = self.key(after)
                if new_cost >= best.get(k, INF):
                    continue
                h = bound(after)
                if h == INF or new_cost + h * PRESS > ceiling:
                    continue
                best[k] = new_cost
                if len(best) > STORED_PER_BUDGET * self.budget:  # memory, not time, runs out
                    raise SearchExhausted("budget", expanded, True)
                states[k] = after
                came_from[k] = (node, after.step, tree, way, free)
                if free:
                    self._continuable.add(k)
                heapq.heappush(frontier, (new_cost + h * PRESS, -new_cost, next(tie), k))
        raise SearchExhausted("exhausted", expanded, False)

    def _visit_successors(
        self,
        ends: Ends,
        state: State,
        node: Hashable,
        cost: int,
        in_the_dark: bool,
        projected: list[int],
        best: dict[Hashable, int],
        states: dict[Hashable, State],
        came_from: dict[Hashable, Any],
        frontier: list[tuple[float, int, int, Hashable]],
        tie: Iterator[int],
        expanded: int,
    ) -> bool:
        """:meth:`run`'s loop over one visit's successors, in order, each state built only
        once its key shows it better than any way found before. True: memory ran out."""
        step, writes, slots = ends.step, ends.writes, ends.slots
        tree, outcomes, keyed = ends.visit
        values = state.values
        bound, ceiling, limit = self.bound, self._ceiling, STORED_PER_BUDGET * self.budget
        for (changed, buffer, memory, presses, way), (written, tail) in zip(
            outcomes, keyed, strict=True
        ):
            new_cost = cost + presses * PRESS + (presses if in_the_dark else 0)
            seen = projected.copy()
            for slot, value in zip(slots, written, strict=True):
                seen[slot] = value
            k = (tuple(seen), step, *tail)
            if new_cost >= best.get(k, INF):
                continue
            new = list(values)
            for w, value in zip(writes, changed, strict=True):
                new[w] = value
            after = State(tuple(new), step, buffer, memory)
            h = bound(after)
            if h == INF or new_cost + h * PRESS > ceiling:
                continue
            best[k] = new_cost
            if len(best) > limit:
                return True
            states[k] = after
            came_from[k] = (node, step, tree, way, False)
            heapq.heappush(frontier, (new_cost + h * PRESS, -new_cost, next(tie), k))
        return False

    def _part_out_of_reach(self, start: State, left: int) -> tuple[bool, int]:
        """Whether one goal variable alone is out of reach from ``start`` (within ``most``
        actions): then the whole goal is too, since every plan for the whole is one for each
        part. Each part's search is small (:data:`PART_WORK` successors) and its space far
        smaller than the whole's — a digit key the belief lost from a keypad makes one value
        untypeable, which the whole search would prove only by walking every other setting's
        values. Proven parts are remembered on the model, per start state. The parts together
        spend at most ``left``, the whole search's own work still to do. Also returns the
        successors the parts' searches generated."""
        goal = self.goal
        spent = 0
        if len(goal.variables) < 2:
            return False, spent
        proven: set[Hashable] = self.compiled.cache.setdefault("parts_out_of_reach", set())
        for name in goal.names:
            value = goal.canonical[name]
            key = (start, name, repr(value), self.most)
            if key in proven:
                return True, spent
            if left - spent <= 0:
                break
            part = TaskSearch(
                self.compiled,
                CompiledGoal.build(self.compiled, {name: value}),
                self.budget,
                min(PART_WORK, left - spent),
                self.most,
            )
            try:
                part.run(start)
            except SearchExhausted as exc:
                spent += part.generated
                if not exc.budget_hit:
                    proven.add(key)
                    return True, spent
                continue
            spent += part.generated
        return False, spent

    @staticmethod
    def _path(
        came_from: dict[
            Hashable, tuple[Hashable, int, VisitTree | None, int | tuple[int, ...], bool] | None
        ],
        node: Hashable,
    ) -> tuple[Visit, ...]:
        visits: list[Visit] = []
        link = came_from[node]
        while link is not None:
            previous, step, tree, way, free = link
            visits.append(Visit(step, _presses(tree, way), free))
            link = came_from[previous]
        return tuple(reversed(visits))
