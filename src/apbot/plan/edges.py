"""A search node's successors: the visits one action starts from it, each explored once.

A visit to a step (``apbot.plan.visits``) is explored from the values its outcome depends on
and cached on them, so the same visit from another node costs nothing; its ends become the
node's successors, their states built only when :class:`apbot.plan.search.TaskSearch` keeps
them. Split from the A* loop (``apbot.plan.search``), which owns the state these methods use.
"""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass
from operator import itemgetter
from typing import Any

from apbot.plan.goals import CompiledGoal
from apbot.plan.visits import (
    VisitTooLarge,
    VisitTree,
    explore_tree,
    keypad_exits,
    keypad_targets,
)
from apbot.sim.compiled import CompiledModel, State

# distinct ends of one visit to one step past which the search gives up (as over budget): every
# end keeps its path, and a step that stores per-programme values while changing the programme
# has combinatorially many
VISIT_LIMIT = 20_000
# visit ends the visit cache may hold before it is emptied (a 1,440-minute clock walked one
# press at a time gives visits of 1,440 ends; an end costs about 200 bytes)
CACHED_ENDS = 500_000


class SearchExhausted(Exception):
    """No plan: the reachable space was searched without finding the goal, or the budget ran
    out. ``expanded`` says how many nodes were expanded."""

    def __init__(self, message: str, expanded: int, budget_hit: bool) -> None:
        super().__init__(message)
        self.expanded = expanded
        self.budget_hit = budget_hit


# one way out of a visit, cached: (values of the step's writes, buffer, memory, presses, and
# the presses themselves — an index into the visit's tree, or the presses when it has none)
Outcome = tuple[tuple[int, ...], str, tuple[int, ...], int, "int | tuple[int, ...]"]
# a successor: (state, presses, the visit's tree or None, index into it or the presses, free)
Edge = tuple[State, int, VisitTree | None, "int | tuple[int, ...]", bool]
# a cached visit: its tree (None: keypad or single presses), outcomes, and per outcome the part
# of a search key it decides: the relevant written values, and (buffer, what memory keeps)
CachedVisit = tuple[
    VisitTree | None, list[Outcome], list[tuple[tuple[int, ...], tuple[Hashable, ...]]]
]


@dataclass(frozen=True)
class Ends:
    """The successors one visit gives a node, their states not yet built: most are dropped
    as no better than a way the search has already found, which their keys alone tell."""

    step: int
    writes: tuple[int, ...]
    slots: tuple[int, ...]  # where the relevant writes sit in a search key's projection
    visit: CachedVisit


def _tupled(picked: Any) -> tuple[int, ...]:
    """What an ``itemgetter`` of one or more items picked, as a tuple."""
    return picked if isinstance(picked, tuple) else (picked,)


class VisitEdges:
    """The successor half of :class:`apbot.plan.search.TaskSearch` (which sets these)."""

    compiled: CompiledModel
    goal: CompiledGoal
    budget: int
    relevant: list[int]
    keypad_step: tuple[bool, ...]
    _memory: tuple[int, ...]
    _visit_cache: dict[Hashable, CachedVisit]
    _slots: dict[int, tuple[tuple[int, ...], tuple[int, ...]]]
    _cached_ends: int
    _footprints: dict[int, tuple[tuple[int, ...], tuple[int, ...]]]
    _keypad_targets: dict[int, list[float]]

    def _edges(self, state: State, may_continue: bool) -> list[Edge | Ends]:
        """Visits to every step one action reaches (the current step only when ``may_continue``),
        then each action that acts without the pointer table (anywhere keys, waits) alone."""
        compiled = self.compiled
        row = compiled.targets[state.step + 1]
        by_step: dict[int, list[int]] = {}
        for action, target in enumerate(row):
            if target < 0 or (target == state.step and not may_continue):
                continue
            if compiled.refusal(state, action) is not None:
                continue
            by_step.setdefault(target, []).append(action)
        edges: list[Edge | Ends] = []
        for step, entry in by_step.items():
            edges.extend(self._visit(state, step, entry))
        for action in compiled.free_actions:
            after = compiled.apply(state, action)
            if after is not None and after != state:
                edges.append((after, 1, None, (action,), True))
        return edges

    def _visit(self, state: State, step: int, entry: list[int]) -> list[Edge | Ends]:
        info = self.compiled.steps[step]
        v = info.variable
        if v < 0 or v not in self.relevant:
            after = self.compiled.apply(state, entry[0])
            return [] if after is None else [(after, 1, None, (entry[0],), False)]
        reads, writes = self._footprint(step)
        continuing = state.step == step
        values = state.values
        cache_key = (
            step,
            tuple(entry),
            tuple(values[r] for r in reads),
            state.buffer if continuing else "",
            continuing,
            state.memory,  # a programme change takes back what a setting kept
        )
        cached = self._visit_cache.get(cache_key)
        if cached is None:
            written = itemgetter(*writes)
            outcomes: list[Outcome]
            tree: VisitTree | None = None
            if self.keypad_step[step]:
                exits = keypad_exits(self.compiled, state, step, entry, self._targets_for(v))
                outcomes = [
                    (_tupled(written(after.values)), after.buffer, after.memory, len(path), path)
                    for after, path in exits
                ]
            else:

                def inner_key(s: State) -> Hashable:
                    # what remembered settings keep tells two ends of a visit apart too (a
                    # press stored a value for the programme its side effect then left)
                    return (written(s.values), s.buffer, s.memory)

                try:
                    tree = explore_tree(
                        self.compiled, state, step, entry, inner_key, limit=VISIT_LIMIT
                    )
                except VisitTooLarge:
                    raise SearchExhausted("budget", self.budget, True) from None
                outcomes = [
                    (_tupled(written(after.values)), after.buffer, after.memory, length, i)
                    for i, (after, length) in enumerate(zip(tree.ends, tree.lengths, strict=True))
                ]
                tree.ends = []  # the paths are all the cache needs of it
            self._cached_ends += len(outcomes)
            if self._cached_ends > CACHED_ENDS:  # a cache, not a store: start afresh
                self._visit_cache.clear()
                self._cached_ends = 0
            picks, _ = self._key_slots(step)
            keypad = self.keypad_step[step]
            keyed: list[tuple[tuple[int, ...], tuple[Hashable, ...]]] = [
                (
                    tuple(changed[i] for i in picks),
                    (buffer if keypad else "", tuple(memory[m] for m in self._memory))
                    if self._memory
                    else (buffer if keypad else "",),
                )
                for changed, buffer, memory, _, _ in outcomes
            ]
            cached = (tree, outcomes, keyed)
            self._visit_cache[cache_key] = cached
        return [Ends(step, writes, self._key_slots(step)[1], cached)]

    def _key_slots(self, step: int) -> tuple[tuple[int, ...], tuple[int, ...]]:
        """For a visit to ``step``: which of its writes are relevant (indices into the
        writes), and where each sits in a search key's projection of the values."""
        found = self._slots.get(step)
        if found is None:
            _, writes = self._footprint(step)
            position = {v: i for i, v in enumerate(self.relevant)}
            picks = tuple(i for i, w in enumerate(writes) if w in position)
            found = (picks, tuple(position[writes[i]] for i in picks))
            self._slots[step] = found
        return found

    def _footprint(self, step: int) -> tuple[tuple[int, ...], tuple[int, ...]]:
        """What a visit to ``step`` can change (its variable, side effects, the settings that
        depend on those) and what its outcome depends on (those, their programmes, guards).
        Visits are cached on the latter, so other variables never force a re-exploration."""
        cached = self._footprints.get(step)
        if cached is None:
            compiled = self.compiled
            info = compiled.steps[step]
            writes = {info.variable} | {target for target, _ in info.side}
            writes |= {d for w in list(writes) for d in compiled.dependents.get(w, ())}
            reads = set(writes) | {
                compiled.vars[w].parent for w in writes if compiled.vars[w].parent >= 0
            }
            reads |= {v for guard in compiled.guards for v, _ in guard.conditions}
            reads |= compiled.condition_variables(info)  # a conditional effect's branch
            cached = (tuple(sorted(reads)), tuple(sorted(writes)))
            self._footprints[step] = cached
        return cached

    def _targets_for(self, v: int) -> list[float]:
        """Values worth typing into keypad variable ``v`` (see :func:`keypad_targets`)."""
        if v not in self._keypad_targets:
            self._keypad_targets[v] = keypad_targets(self.compiled, self.goal, v)
        return self._keypad_targets[v]
