"""The agent's belief: a model of the appliance and where it thinks the appliance is in it.

The belief is advanced by simulating each action the agent performs, corrected from what the
feedback shows, and carried over when the model is repaired (values by name, the feature
pointer by feature and step).
"""

from __future__ import annotations

from typing import Any

from apbot.model.domain import ValueProblem, normalise
from apbot.model.schema import ApplianceModel
from apbot.sim.compiled import CompiledModel, State, compiled_model
from apbot.sim.simulator import Observation, Simulator


class Belief:
    """A model plus a state in it. ``state`` is what the agent believes the appliance is in."""

    def __init__(self, model: ApplianceModel) -> None:
        self.compiled: CompiledModel = compiled_model(model)
        self.state: State = self.compiled.initial_state()
        self._simulator = Simulator(self.compiled)

    @property
    def model(self) -> ApplianceModel:
        return self.compiled.model

    def advance(self, action: str, seconds: float | None = None) -> bool:
        """Simulate ``action``; False (state unchanged) when the model says it is refused."""
        index = self.compiled.action_index.get(action)
        if index is None:
            return False
        after = self.compiled.apply(self.state, index, seconds)
        if after is None:
            return False
        self.state = after
        return True

    def expected(self) -> Observation:
        """What the model says the display shows now."""
        return self._simulator.reset(self.state)

    def value(self, name: str) -> Any:
        return self.compiled.value(self.state, name)

    def values(self) -> dict[str, Any]:
        return self.compiled.assignment(self.state)

    def initial_value(self, name: str, state: State | None = None) -> Any:
        """What ``name`` starts from (in the programme ``state`` is in; default: now)."""
        state = self.state if state is None else state
        var = self.compiled.vars[self.compiled.var_index[name]]
        domain = var.domain(state.values)
        return None if domain is None else domain.values[domain.initial]

    def _index(self, name: str, value: Any) -> int | None:
        v = self.compiled.var_index[name]
        var = self.compiled.vars[v]
        domain = var.domain(self.state.values)
        if domain is None:
            return None
        try:
            canonical = normalise(var.spec, value, domain)
        except ValueProblem:
            return None
        return domain.index.get(canonical)

    def set_value(self, name: str, value: Any) -> bool:
        """Believe ``name`` has ``value`` now (when the model allows it); True if it did."""
        index = self._index(name, value)
        if index is None:
            return False
        v = self.compiled.var_index[name]
        if self.state.values[v] == index:
            return True
        values = list(self.state.values)
        values[v] = index
        memory = self.state.memory
        for dependent in self.compiled.dependents.get(v, ()):
            domain = self.compiled.vars[dependent].domain(values)
            slots = self.compiled.memory_slots.get(dependent)
            if slots is not None and domain is not None:  # it shows what it kept there
                values[dependent] = memory[slots[index]]
                continue
            values[dependent] = -1 if domain is None else domain.initial
        self.state = self.compiled.kept_in_sync(self.state._replace(values=tuple(values)))
        return True

    def pointer(self) -> tuple[str, int] | None:
        """The feature and step the belief is in (None: no feature active)."""
        if self.state.step < 0:
            return None
        step = self.compiled.steps[self.state.step]
        return step.feature, step.index

    def set_pointer(self, pointer: tuple[str, int] | None, buffer: str = "") -> None:
        """Believe the appliance is in this feature step (a keypad buffer ``buffer`` typed)."""
        step = -1
        if pointer is not None:
            step = next(
                (i for i, s in enumerate(self.compiled.steps) if (s.feature, s.index) == pointer),
                -1,
            )
        self.state = self.state._replace(step=step, buffer=buffer if step >= 0 else "")

    def replace(self, model: ApplianceModel, pointer: tuple[str, int] | None = None) -> None:
        """Switch to a repaired model, keeping every value that still fits it."""
        values = self.values()
        old_pointer = self.pointer() if pointer is None else pointer
        buffer = self.state.buffer if old_pointer == self.pointer() else ""
        self.compiled = CompiledModel(model)
        self._simulator = Simulator(self.compiled)
        self.state = self.compiled.initial_state()
        order = sorted(
            values,
            key=lambda n: (
                self.compiled.vars[self.compiled.var_index[n]].parent
                if n in self.compiled.var_index
                else 0
            ),
        )
        for name in order:  # parents (parent index -1) before their dependents
            if name in self.compiled.var_index and values[name] is not None:
                self.set_value(name, values[name])
        self.set_pointer(old_pointer, buffer)
