"""Checking that a state handed in from outside (a caller's plan, a belief) is a state of a
compiled model, with an error that says what is wrong.

Kept apart from the step semantics (:mod:`apbot.sim.compiled`): stepping trusts its states,
and only the public entry points (the simulator, the planner) check the ones they are given.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from apbot.sim.parts import State

if TYPE_CHECKING:
    from apbot.sim.compiled import CompiledModel


def check_state(cm: CompiledModel, state: Any, argument: str = "state") -> None:
    """Raise a clear error unless ``state`` is a state of this model.

    A state is a :class:`State` (from ``initial_state()``, ``Simulator.state`` or an
    earlier plan): one value index per variable within its domain (``-1`` for a setting
    absent in the current programme), a step id or ``-1``, and a buffer of digits.
    """
    if not isinstance(state, State):
        raise TypeError(
            f"{argument} must be a State (Simulator.state, CompiledModel.initial_state()) "
            f"or None, not {type(state).__name__}"
        )
    values, step, buffer = state.values, state.step, state.buffer
    if not isinstance(values, tuple) or len(values) != len(cm.vars):
        raise ValueError(
            f"{argument}.values must hold one value index for each of the model's "
            f"{len(cm.vars)} variables"
        )
    for i, var in enumerate(cm.vars):
        index = values[i]
        if isinstance(index, bool) or not isinstance(index, int):
            raise ValueError(f"{argument}.values[{i}] ({var.name}) is not an index: {index!r}")
    for i, var in enumerate(cm.vars):  # parents first: a case depends on its parent
        if var.parent < 0 and not 0 <= values[i] < len(var.domains[0] or ()):
            raise ValueError(
                f"{argument}.values[{i}]: {values[i]} is not an index of {var.name}'s "
                f"{len(var.domains[0] or ())} values"
            )
    for i, var in enumerate(cm.vars):
        if var.parent >= 0:
            domain = var.domain(values)
            allowed = f"0 to {len(domain) - 1}" if domain is not None else "-1 (absent)"
            if (domain is None and values[i] != -1) or (
                domain is not None and not 0 <= values[i] < len(domain)
            ):
                raise ValueError(
                    f"{argument}.values[{i}]: {values[i]} is not an index of {var.name} "
                    f"in this programme ({allowed})"
                )
    if isinstance(step, bool) or not isinstance(step, int) or not -1 <= step < len(cm.steps):
        raise ValueError(
            f"{argument}.step must be -1 or a step id below {len(cm.steps)}, not {step!r}"
        )
    if not isinstance(buffer, str) or not (buffer == "" or buffer.isdigit()):
        raise ValueError(f"{argument}.buffer must be a string of typed digits, not {buffer!r}")
    _check_memory(cm, state, argument)


def _check_memory(cm: CompiledModel, state: State, argument: str) -> None:
    """The kept values of ``remember`` settings: one index per (setting, programme) in
    that programme's domain, and the current programme's equal to what is shown."""
    memory = state.memory
    if not isinstance(memory, tuple) or len(memory) != len(cm.memory_defaults):
        raise ValueError(
            f"{argument}.memory must hold {len(cm.memory_defaults)} kept values (one per "
            "remembered setting and programme); start from initial_state()"
        )
    for v, slots in cm.memory_slots.items():
        var = cm.vars[v]
        for case, slot in enumerate(slots):
            domain = var.domains[case]
            if slot < 0 or domain is None:
                continue
            index = memory[slot]
            if isinstance(index, bool) or not isinstance(index, int):
                raise ValueError(f"{argument}.memory[{slot}] is not an index: {index!r}")
            if not 0 <= index < len(domain):
                raise ValueError(
                    f"{argument}.memory[{slot}]: {index} is not an index of {var.name}'s "
                    f"{len(domain)} values in case {case}"
                )
            if case == state.values[var.parent] and index != state.values[v]:
                raise ValueError(
                    f"{argument}.memory[{slot}] keeps {index} for {var.name} in the current "
                    f"programme, but {var.name} is {state.values[v]}"
                )
