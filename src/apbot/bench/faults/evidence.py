"""Whether a fault matters: a sequence of presses after which the faulty model and the truth
disagree on what the panel shows, on whether a key is taken, or on a setting's value.

A fault nothing can reveal would be dead weight in the study (it could never mislead the
planner or the loop); the tests use :func:`first_difference` to show every kind changes
behaviour, and ``benchmarks/fault_kinds.py`` counts faults it cannot tell apart.
"""

from __future__ import annotations

from collections import deque
from typing import Any

from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import CompiledModel, State, compiled_model
from apbot.sim.simulator import Simulator

MAX_STATES = 4_000  # joint states explored breadth first
MAX_RUN = 40  # presses of one key in a row tried from each shallow state (range ends, wrap)
RUN_DEPTH = 3  # how deep in the search those runs start


class _Side:
    """One model under test: its compiled tables and what its panel shows in a state."""

    def __init__(self, model: ApplianceModel) -> None:
        self.compiled: CompiledModel = compiled_model(model)
        self.simulator = Simulator(self.compiled)
        self.shown: dict[State, str] = {}

    def text(self, state: State) -> str:
        found = self.shown.get(state)
        if found is None:
            self.simulator.state = state
            found = self.shown[state] = self.simulator.observe().text
        return found

    def step(self, state: State, action: str) -> tuple[State, bool]:
        index = self.compiled.action_index.get(action)
        new = None if index is None else self.compiled.apply(state, index)
        return (state, False) if new is None else (new, True)

    def values(self, state: State, names: list[str]) -> tuple[Any, ...]:
        return tuple(self.compiled.value(state, n) for n in names)


def first_difference(
    truth: ApplianceModel, faulty: ApplianceModel, max_states: int = MAX_STATES
) -> list[str] | None:
    """The shortest-found action sequence (of the true model's actions) after which the two
    models disagree: the panel text, a key taken or refused, or the value of a variable both
    have. ``[]`` when they differ before any press; None when the search found no difference
    within its budget. A key the faulty model does not know counts as refused there."""
    real, belief = _Side(truth), _Side(faulty)
    shared = [n for n in truth.variables if n in faulty.variables]
    actions = list(truth.actions)

    def differ(a: State, b: State, taken: bool, believed: bool) -> bool:
        return (
            taken != believed
            or real.text(a) != belief.text(b)
            or real.values(a, shared) != belief.values(b, shared)
        )

    start = (real.compiled.initial_state(), belief.compiled.initial_state())
    if differ(*start, True, True):
        return []
    paths: dict[tuple[State, State], list[str]] = {start: []}
    queue = deque([start])
    while queue and len(paths) < max_states:
        pair = queue.popleft()
        path = paths[pair]
        for action in actions:
            a, taken = real.step(pair[0], action)
            b, believed = belief.step(pair[1], action)
            if differ(a, b, taken, believed):
                return [*path, action]
            if (a, b) not in paths:
                paths[a, b] = [*path, action]
                queue.append((a, b))
            if len(path) < RUN_DEPTH:
                found = _run(real, belief, (a, b), action, differ)
                if found is not None:
                    return [*path, *[action] * (found + 1)]
    return None


def _run(
    real: _Side, belief: _Side, pair: tuple[State, State], action: str, differ: Any
) -> int | None:
    """Press ``action`` again and again from ``pair``: the number of extra presses after which
    the models disagree, or None (a run stops when the joint state repeats)."""
    seen = {pair}
    a, b = pair
    for presses in range(1, MAX_RUN + 1):
        a, taken = real.step(a, action)
        b, believed = belief.step(b, action)
        if differ(a, b, taken, believed):
            return presses
        if (a, b) in seen:
            return None
        seen.add((a, b))
    return None
