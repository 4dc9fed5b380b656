"""What a compiled model is made of: its state, its per-variable, per-step, per-cycle and
per-guard records, and the codes its effect tables and refusals use.

They live apart from :mod:`apbot.sim.compiled` (the step semantics) and
:mod:`apbot.sim.compiler` (which builds them) because the planner and the checkers read these
records directly, without stepping or building anything.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any, NamedTuple

from apbot.model.domain import Domain
from apbot.model.schema import DiscreteVariable, NumericVariable, TimeVariable

NONE, TABLE, DIGIT, CLEAR, COND = 0, 1, 2, 3, 4

# rejection reasons (negative codes; a guard's refusal is its index >= 0)
NOT_HERE = -1
TOO_SHORT = -2


class State(NamedTuple):
    """An appliance state: value indices, feature-pointer step id, keypad buffer, and the
    value each ``remember`` setting keeps for each programme (see ``memory_slots``). Hashable."""

    values: tuple[int, ...]
    step: int
    buffer: str
    memory: tuple[int, ...] = ()


@dataclass(frozen=True)
class VarInfo:
    """A variable with its domains: one, or one per value of the parent (``None`` = absent)."""

    name: str
    spec: DiscreteVariable | NumericVariable | TimeVariable
    domains: tuple[Domain | None, ...]
    parent: int  # index of the variable selecting the case, or -1

    def domain(self, values: tuple[int, ...] | list[int]) -> Domain | None:
        """The domain in force for these values."""
        return self.domains[values[self.parent]] if self.parent >= 0 else self.domains[0]

    def case(self, values: tuple[int, ...] | list[int]) -> int:
        return values[self.parent] if self.parent >= 0 else 0


@dataclass(frozen=True)
class StepInfo:
    """A compiled feature step."""

    feature: str
    index: int
    variable: int  # -1 when the step adjusts no variable
    actions: frozenset[int]
    effects: dict[int, tuple[Any, ...]]  # action -> (kind, per-case tables | digit)
    side: tuple[tuple[int, tuple[tuple[int, ...] | None, ...]], ...]  # (var, per-case tables)
    next_step: int  # the next step of the same feature, or -1
    show_on_entry: bool = False  # the entering action only shows the value
    optional: bool = False  # the step may be skipped (``Step.optional``)
    timeout: float | None = None  # seconds without a key that return to no feature
    leave: bool = False  # an anywhere step that returns the pointer to no feature
    blank_clears: bool = False  # a non-digit key of this keypad step empties the buffer
    forgets: frozenset[int] = frozenset()  # variables the step's side effects ``reset``


@dataclass(frozen=True)
class CycleInfo:
    """A compiled cycle: while ``conditions`` hold for ``lasts`` × ``scale`` seconds, then the
    side effects ``side`` (as a step's) apply."""

    name: str
    conditions: tuple[tuple[int, frozenset[int]], ...]
    lasts: int
    scale: float
    side: tuple[tuple[int, tuple[tuple[int, ...] | None, ...]], ...]
    forgets: frozenset[int]


@dataclass(frozen=True)
class GuardInfo:
    conditions: tuple[tuple[int, frozenset[int]], ...]
    allowed: frozenset[int]
    display: str
    name: str
    hide: bool = False


def leaves(effects: Iterable[tuple[Any, ...]]) -> list[tuple[Any, ...]]:
    """Compiled effects with every conditional replaced by the effects it may apply: what an
    analysis over all states (a lower bound, reachable values) must consider."""
    found: list[tuple[Any, ...]] = []
    pending = list(effects)
    while pending:
        effect = pending.pop()
        if effect[0] == COND:
            pending += [effect[2], effect[3]]
        else:
            found.append(effect)
    return found
