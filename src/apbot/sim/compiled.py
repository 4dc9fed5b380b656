"""The semantics of a model, compiled into lookup tables so that one step costs a few microseconds.

State
    A :class:`State` holds the index of every variable's value in its current domain (``-1``
    when a programme-dependent setting does not exist in the current programme), the feature
    pointer (a global step id, ``-1`` before any feature), and the keypad input buffer.

Feature pointer (kept from the paper)
    An action that belongs to the current step keeps the pointer there; otherwise one that
    belongs to the next step of the same feature advances to it; otherwise the action enters
    the first feature (in declaration order) whose first step contains it. An action that fits
    none of these is refused. The keypad buffer empties whenever the pointer moves to another
    step, so a digit typed for the timer never leaks into the clock. Past an ``optional``
    next step, the step after it is accepted too. Keys listed under ``anywhere`` bypass the
    pointer (it stays, or with ``leave`` returns to no feature; the buffer empties), and a
    ``wait`` at least as long as the current step's ``timeout`` returns it to no feature.

Effects
    The action that enters a step applies the step's effect too, unless the step says
    ``on_entry: show``. Every value-changing effect (next, prev, toggle, go-to, add, skip,
    reset) compiles to a table
    ``new_index = table[current_index]`` per case of the variable; a keypad digit appends to the
    buffer and sets the variable when the buffer parses to one of its values; a conditional
    effect picks its branch on the state before the action. Side effects
    (``set``, ``reset``) of a step follow its main effect. When a programme is chosen, settings
    that depend on it return to that programme's defaults: whenever it changes, and also when
    it is assigned without changing (a go-to key pressed again, a ``reset`` or ``set`` when the
    appliance is switched off) — a real appliance re-applies the programme's defaults then.

Guards
    Checked before anything else: while a guard's condition holds, only its listed actions are
    accepted (power off, child lock, running).

The state changes (effects, resets, memory, a cycle's end) are :mod:`apbot.sim.compiled_effects`.
"""

from __future__ import annotations

from typing import Any

from apbot.model.display import display_value
from apbot.model.schema import ApplianceModel
from apbot.sim.compiled_effects import Effects
from apbot.sim.compiler import (
    compile_anywhere,
    compile_cycles,
    compile_guards,
    compile_steps,
    compile_targets,
    compile_variable,
    first_steps,
)
from apbot.sim.parts import (
    CLEAR,
    COND,
    DIGIT,
    NONE,
    NOT_HERE,
    TABLE,
    TOO_SHORT,
    CycleInfo,
    GuardInfo,
    State,
    StepInfo,
    VarInfo,
    leaves,
)
from apbot.sim.state_check import check_state

__all__ = [
    "CLEAR",
    "COND",
    "DIGIT",
    "NONE",
    "NOT_HERE",
    "TABLE",
    "TOO_SHORT",
    "CompiledModel",
    "CycleInfo",
    "GuardInfo",
    "State",
    "StepInfo",
    "VarInfo",
    "compiled_model",
    "leaves",
]


class CompiledModel(Effects):
    """Lookup tables for a validated model. Build once, step many times."""

    def __init__(self, model: ApplianceModel) -> None:
        self.model = model
        names = list(model.variables)
        self.var_index = {name: i for i, name in enumerate(names)}
        self.action_names = list(model.actions)
        self.action_index = {name: i for i, name in enumerate(self.action_names)}
        self.vars = tuple(compile_variable(self, name) for name in names)
        self.dependents: dict[int, tuple[int, ...]] = {}
        for i, var in enumerate(self.vars):
            if var.parent >= 0:
                self.dependents.setdefault(var.parent, ())
                self.dependents[var.parent] += (i,)
        self.steps = compile_steps(self)
        self.anywhere_steps = compile_anywhere(self)
        # every step an analysis must know about: features' (ids as in State.step), then anywhere
        self.all_steps = self.steps + self.anywhere_steps
        self.anywhere = {a: info for info in self.anywhere_steps for a in sorted(info.actions)}
        self.waits = {
            self.action_index[name]: float(spec.seconds or 0)
            for name, spec in model.actions.items()
            if spec.skill == "wait"
        }
        # actions that do not go through the feature pointer's table
        self.free_actions = tuple(sorted({*self.anywhere, *self.waits}))
        self.short_enters = frozenset(
            self.action_index[name]
            for name, spec in model.actions.items()
            if spec.too_short == "enters"
        )
        self.cycles = compile_cycles(self)
        self.first_steps = first_steps(self)
        self.targets = compile_targets(self)
        self.guards = compile_guards(self)
        self.hold_seconds = tuple(
            model.actions[a].seconds if model.actions[a].skill == "hold" else None
            for a in self.action_names
        )
        self.digits = tuple(
            str(model.actions[a].digit) if model.actions[a].digit is not None else ""
            for a in self.action_names
        )
        self.feature_names = list(model.features)
        # ``remember`` settings: per variable, its memory slot for each case (-1: no domain)
        self.memory_slots: dict[int, tuple[int, ...]] = {}
        defaults: list[int] = []
        for v, var in enumerate(self.vars):
            if var.parent >= 0 and var.spec.remember:
                slots = []
                for domain in var.domains:
                    slots.append(-1 if domain is None else len(defaults))
                    if domain is not None:
                        defaults.append(domain.initial)
                self.memory_slots[v] = tuple(slots)
        self.memory_defaults = tuple(defaults)
        self.cache: dict[str, Any] = {}  # planner data derived from this model, built lazily

    def memory_of(self, variables: set[int] | list[int]) -> tuple[int, ...]:
        """The memory slots of the ``remember`` settings among ``variables``: a state reduced
        to those variables must keep these too."""
        return tuple(
            slot for v in sorted(variables) for slot in self.memory_slots.get(v, ()) if slot >= 0
        )

    def condition_variables(self, step: StepInfo) -> set[int]:
        """The variables a step's conditional effects read."""
        found: set[int] = set()
        pending = list(step.effects.values())
        while pending:
            effect = pending.pop()
            if effect[0] == COND:
                found.update(v for v, _ in effect[1])
                pending += [effect[2], effect[3]]
        return found

    def influencers(self, variables: set[int]) -> set[int]:
        """``variables`` with everything that decides how they change: the programmes
        selecting their domains and the variables their steps' conditional effects read,
        closed under both — a state reduced to these evolves them exactly."""
        reads: dict[int, set[int]] = {}
        for step in self.steps:
            if step.variable >= 0:
                reads.setdefault(step.variable, set()).update(self.condition_variables(step))
        kept = set(variables)
        frontier = list(kept)
        while frontier:
            v = frontier.pop()
            parent = self.vars[v].parent
            for u in ({parent} if parent >= 0 else set()) | reads.get(v, set()):
                if u not in kept:
                    kept.add(u)
                    frontier.append(u)
        return kept

    # --- running -----------------------------------------------------------------------------

    def initial_state(self) -> State:
        """Every variable at its initial value; no feature active; empty buffer."""
        values: list[int] = []
        for var in self.vars:
            if var.parent < 0:
                domain = var.domains[0]
                assert domain is not None
                values.append(domain.initial)
            else:
                values.append(-1)
        for i, var in enumerate(self.vars):
            if var.parent >= 0:
                domain = var.domain(values)
                values[i] = -1 if domain is None else domain.initial
        return State(tuple(values), -1, "", self.memory_defaults)

    def check_state(self, state: Any, argument: str = "state") -> None:
        """Raise a clear error unless ``state`` is a state of this model.

        A state is a :class:`State` (from ``initial_state()``, ``Simulator.state`` or an
        earlier plan): one value index per variable within its domain (``-1`` for a setting
        absent in the current programme), a step id or ``-1``, and a buffer of digits.
        """
        check_state(self, state, argument)

    def hiding_guard(self, state: State) -> GuardInfo | None:
        """A guard with ``hide`` that holds now: the display shows only its text."""
        for guard in self.guards:
            if guard.hide and all(state.values[v] in ok for v, ok in guard.conditions):
                return guard
        return None

    def refusal(self, state: State, action: int) -> int | None:
        """Why ``action`` would be refused in ``state`` (guard index or negative code), or None."""
        if action in self.waits:
            return None  # nothing stops anyone from waiting
        values = state.values
        for g, guard in enumerate(self.guards):
            if action not in guard.allowed and all(values[v] in ok for v, ok in guard.conditions):
                return g
        if action not in self.anywhere and self.targets[state.step + 1][action] < 0:
            return NOT_HERE
        return None

    def apply(self, state: State, action: int, seconds: float | None = None) -> State | None:
        """The state after ``action``, or None when the appliance refuses it."""
        if action in self.waits:
            return self._wait(state, self.waits[action] if seconds is None else seconds)
        values = state.values
        for guard in self.guards:
            if action not in guard.allowed:
                for v, ok in guard.conditions:
                    if values[v] not in ok:
                        break
                else:
                    return None
        needed = self.hold_seconds[action]
        short = needed is not None and seconds is not None and seconds + 1e-9 < needed
        anywhere = self.anywhere.get(action)
        if anywhere is not None:
            if short:
                return None  # an anywhere hold has no procedure to enter when released early
            target = -1 if anywhere.leave else state.step
            effect = self._resolved(anywhere.effects[action], values)
            return self._effects(state, anywhere, effect, target, "", effect[0])
        target = self.targets[state.step + 1][action]
        if target < 0:
            return None
        if short:
            if action not in self.short_enters:
                return None
            # released early: the procedure moves as usual, the change does not happen
            return state if target == state.step else State(values, target, "", state.memory)
        step = self.steps[target]
        buffer = state.buffer if target == state.step else ""
        effect = self._resolved(step.effects[action], values)
        kind = NONE if step.show_on_entry and target != state.step else effect[0]
        if kind == NONE and step.blank_clears and effect[0] == NONE:
            buffer = ""  # a non-digit key ends the typing (Entry.other_keys)
        return self._effects(state, step, effect, target, buffer, kind)

    # --- reading -----------------------------------------------------------------------------

    def value(self, state: State, name: str) -> Any:
        """The canonical value of a variable (None when absent in the current programme)."""
        v = self.var_index[name]
        index = state.values[v]
        domain = self.vars[v].domain(state.values)
        return None if index < 0 or domain is None else domain.values[index]

    def assignment(self, state: State) -> dict[str, Any]:
        """Every variable's canonical value."""
        return {var.name: self.value(state, var.name) for var in self.vars}

    def focus(self, state: State) -> int:
        """The variable the display is showing: the current step's, else the next step's."""
        if state.step < 0:
            return -1
        step = self.steps[state.step]
        if step.variable >= 0:
            return step.variable
        if step.next_step >= 0:
            return self.steps[step.next_step].variable
        return -1

    def render_value(self, state: State, v: int) -> str:
        """A value as the display prints it (unit, time style)."""
        return display_value(self.vars[v].spec, self.value(state, self.vars[v].name))


_COMPILED: dict[int, tuple[ApplianceModel, CompiledModel]] = {}


def compiled_model(model: ApplianceModel | CompiledModel) -> CompiledModel:
    """A compiled model, reusing earlier compilations of the same model object.

    Models are immutable, so a compilation (and the planner data cached on it) stays valid.
    """
    if isinstance(model, CompiledModel):
        return model
    hit = _COMPILED.get(id(model))
    if hit is not None and hit[0] is model:
        return hit[1]
    if len(_COMPILED) >= 256:
        _COMPILED.pop(next(iter(_COMPILED)))
    compiled = CompiledModel(model)
    _COMPILED[id(model)] = (model, compiled)
    return compiled
