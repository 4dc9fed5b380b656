"""Goals in compiled form: which value index satisfies each goal variable in each case."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from apbot.sim.compiled import CompiledModel, State


@dataclass(frozen=True)
class CompiledGoal:
    """A canonical goal as index lookups. ``wanted[k][case]`` is the goal index or -2."""

    names: tuple[str, ...]
    variables: tuple[int, ...]
    wanted: tuple[tuple[int, ...], ...]
    canonical: dict[str, Any]

    @classmethod
    def build(cls, compiled: CompiledModel, goal: Mapping[str, Any]) -> CompiledGoal:
        names = tuple(goal)
        variables = tuple(compiled.var_index[n] for n in names)
        wanted = tuple(
            tuple(-2 if d is None else d.index.get(goal[n], -2) for d in compiled.vars[v].domains)
            for n, v in zip(names, variables, strict=True)
        )
        return cls(names, variables, wanted, dict(goal))

    def case_conflict(self, compiled: CompiledModel) -> bool:
        """Whether no value of some programme lets all its goal settings hold at once: each
        goal value exists only in some programmes' domains (a time of 1:30 only for SLOW, a
        temperature of 170° only for BAKE), and a goal holds in one programme. A proof of
        "out of reach" that needs no search at all."""
        by_parent: dict[int, set[int]] = {}
        for v, wanted in zip(self.variables, self.wanted, strict=True):
            parent = compiled.vars[v].parent
            if parent < 0:
                continue
            cases = {case for case, index in enumerate(wanted) if index >= 0}
            by_parent[parent] = by_parent.get(parent, cases) & cases
        for parent, cases in by_parent.items():
            if parent in self.variables:  # the programme itself is a goal: its value only
                k = self.variables.index(parent)
                cases &= {self.wanted[k][0]}
            if not cases:
                return True
        return False

    def holds(self, compiled: CompiledModel, state: State) -> bool:
        values = state.values
        for v, wanted in zip(self.variables, self.wanted, strict=True):
            var = compiled.vars[v]
            index = values[v]
            if index < 0 or wanted[values[var.parent] if var.parent >= 0 else 0] != index:
                return False
        return True
