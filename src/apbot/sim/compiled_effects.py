"""How one accepted action, a wait or a cycle's end changes a compiled model's state: effect
tables applied, keypad digits typed, a programme's settings reset or taken back from memory,
and a cycle's side effects. Apart from :mod:`apbot.sim.compiled`, which builds the tables,
decides whether an action is accepted and which step it reaches, and reads values back,
because these compute the next state once that is decided; a part of
:class:`apbot.sim.compiled.CompiledModel`."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import Domain
from apbot.model.effects import parse_entry, type_digit
from apbot.model.schema import DiscreteVariable
from apbot.model.values import format_hms, tidy_number
from apbot.sim.parts import CLEAR, COND, DIGIT, TABLE, CycleInfo, State, StepInfo, VarInfo


class Effects:
    """The state changes of the step semantics (a part of
    :class:`apbot.sim.compiled.CompiledModel`)."""

    vars: tuple[VarInfo, ...]
    steps: tuple[StepInfo, ...]
    cycles: tuple[CycleInfo, ...]
    dependents: dict[int, tuple[int, ...]]
    memory_slots: dict[int, tuple[int, ...]]
    memory_defaults: tuple[int, ...]

    def cycle_running(self, state: State, c: int) -> bool:
        """Whether cycle ``c``'s condition holds in ``state``."""
        return all(state.values[v] in ok for v, ok in self.cycles[c].conditions)

    def cycle_seconds(self, state: State, c: int) -> float:
        """How long cycle ``c`` lasts, read from its length variable now."""
        cycle = self.cycles[c]
        domain = self.vars[cycle.lasts].domains[0]
        assert domain is not None and domain.magnitudes is not None
        return domain.magnitudes[state.values[cycle.lasts]] * cycle.scale

    def end_cycle(self, state: State, c: int) -> State:
        """The state when cycle ``c`` ends by itself: its side effects, as a step's apply."""
        cycle = self.cycles[c]
        new = list(state.values)
        memory = list(state.memory) if self.memory_slots else None
        self._apply_sides(new, cycle.side, cycle.forgets, memory)
        ended = State(tuple(new), state.step, state.buffer, state.memory)
        if memory is None:
            return ended
        return self.kept_in_sync(ended._replace(memory=tuple(memory)))

    def kept_in_sync(self, state: State) -> State:
        """``state`` with each ``remember`` setting's kept value for the current programme set
        to the value it has (after its values were set from outside, e.g. by a belief)."""
        if not self.memory_slots:
            return state
        memory = list(state.memory)
        for v, slots in self.memory_slots.items():
            slot = slots[state.values[self.vars[v].parent]]
            if slot >= 0 and state.values[v] >= 0:
                memory[slot] = state.values[v]
        return state._replace(memory=tuple(memory))

    @staticmethod
    def _resolved(effect: tuple[Any, ...], values: tuple[int, ...]) -> tuple[Any, ...]:
        """A conditional effect's branch for ``values`` (conditions read the state before the
        action); any other effect as it is."""
        while effect[0] == COND:
            effect = effect[2] if all(values[c] in ok for c, ok in effect[1]) else effect[3]
        return effect

    def _wait(self, state: State, seconds: float) -> State:
        """``seconds`` without a key: a step's timeout returns the appliance to no feature."""
        if state.step >= 0:
            timeout = self.steps[state.step].timeout
            if timeout is not None and seconds + 1e-9 >= timeout:
                return State(state.values, -1, "", state.memory)
        return state

    def _effects(
        self,
        state: State,
        step: StepInfo,
        effect: tuple[Any, ...],
        target: int,
        buffer: str,
        kind: int,
    ) -> State:
        """Apply a step's (resolved) ``effect`` of one action, as ``kind``, and its side
        effects."""
        values = state.values
        new = list(values)
        v = step.variable
        if kind == TABLE:
            var = self.vars[v]
            current = new[v]
            if current >= 0:
                table = effect[1][var.case(new)]
                if table is not None:
                    new[v] = table[current]
        elif kind == DIGIT:
            new[v], buffer = self._type(new, v, buffer, str(effect[1]))
        elif kind == CLEAR:
            buffer = ""
            var = self.vars[v]
            if new[v] >= 0:
                table = effect[1][var.case(new)]
                if table is not None:
                    new[v] = table[new[v]]
        memory = list(state.memory) if self.memory_slots else None
        if (
            v >= 0
            and v in self.dependents
            and (new[v] != values[v] or kind == CLEAR or (kind == TABLE and effect[2]))
        ):
            self._reset_dependents(new, v, values[v], memory)
        if (
            memory is not None
            and v in self.memory_slots
            and (kind == CLEAR or (kind == TABLE and effect[3]))
        ):
            self._forget(memory, v)
        self._apply_sides(new, step.side, step.forgets, memory)
        if memory is None:
            return State(tuple(new), target, buffer)
        for r, slots in self.memory_slots.items():  # what a setting shows is what it keeps
            slot = slots[new[self.vars[r].parent]]
            if slot >= 0:
                memory[slot] = new[r]
        return State(tuple(new), target, buffer, tuple(memory))

    def _apply_sides(
        self,
        new: list[int],
        side: tuple[tuple[int, tuple[tuple[int, ...] | None, ...]], ...],
        forgets: frozenset[int],
        memory: list[int] | None,
    ) -> None:
        """A step's or a cycle's side effects on ``new``, in place: each assigns (so dependents
        return to their programme's defaults) and may forget a remembered value."""
        for target_var, tables in side:
            before = new[target_var]
            var = self.vars[target_var]
            if before >= 0:
                table = tables[var.case(new)]
                if table is not None:
                    new[target_var] = table[before]
            if target_var in self.dependents:
                self._reset_dependents(new, target_var, before, memory)
            if memory is not None and target_var in forgets and target_var in self.memory_slots:
                self._forget(memory, target_var)

    def _reset_dependents(
        self, values: list[int], parent: int, before: int, memory: list[int] | None
    ) -> None:
        """A programme was chosen (``before``: its value until now): its settings take the
        new programme's default — or, for a ``remember`` setting, keep this programme's value
        and take back the one kept for the new programme (unchanged if it did not change)."""
        for d in self.dependents[parent]:
            slots = self.memory_slots.get(d) if memory is not None else None
            if slots is not None and memory is not None:
                if values[parent] == before:
                    continue
                if slots[before] >= 0 and values[d] >= 0:
                    memory[slots[before]] = values[d]
                slot = slots[values[parent]]
                values[d] = -1 if slot < 0 else memory[slot]
                continue
            domain = self.vars[d].domain(values)
            values[d] = -1 if domain is None else domain.initial

    def _forget(self, memory: list[int], v: int) -> None:
        """A ``reset`` of a ``remember`` setting forgets every programme's value."""
        for slot in self.memory_slots[v]:
            if slot >= 0:
                memory[slot] = self.memory_defaults[slot]

    def _type(self, values: list[int], v: int, buffer: str, digit: str) -> tuple[int, str]:
        var = self.vars[v]
        entry = var.spec.entry if not isinstance(var.spec, DiscreteVariable) else None
        domain = var.domain(values)
        if entry is None or domain is None:
            return values[v], buffer
        buffer = type_digit(buffer, digit, entry)
        magnitude = parse_entry(buffer, entry)
        index = self.magnitude_index(domain, magnitude)
        return (values[v] if index is None else index), buffer

    @staticmethod
    def magnitude_index(domain: Domain, magnitude: float | None) -> int | None:
        if magnitude is None:
            return None
        return domain.index.get(_canonical(domain, magnitude))


def _canonical(domain: Domain, magnitude: float) -> Any:
    if domain.kind == "time":
        return format_hms(int(magnitude))
    return tidy_number(magnitude)
