"""Switches a goal's settings need: one a setting's own procedure turns on (READY AT turns the
finish timer on), and one a setting exists or moves only under (a temperature kept only with
the HEATER on)."""

from __future__ import annotations

from typing import Any

from apbot.model.schema import DiscreteVariable, GoTo
from apbot.read.goal_text import Text, negative_around
from apbot.read.goal_view import Goal, Model, VarInfo, own_concepts, own_stems, step_effects


def entry_switches(view: Model, goal: Goal) -> None:
    """A setting entered through a switch ("READY AT" turns the finish timer on, then sets the
    time) implies that switch on, unless the instruction already said otherwise."""
    for _feature, steps in view.model.features.items():
        for index, step in enumerate(steps):
            if step.variable not in goal:
                continue
            for earlier in steps[:index]:
                target = earlier.variable
                info = view.infos.get(target or "")
                if info is None or info.role != "switch" or target in goal:
                    continue
                effects = [effect for _a, effect in step_effects(earlier)]
                if all(effect == "toggle" for effect in effects) and effects:
                    goal[info.name] = info.on


def closing_switches(view: Model, text: Text, goal: Goal) -> None:
    """A setting whose procedure ends by turning a switch on (a schedule's hour and minute,
    then OK arms the schedule) implies that switch on: the confirmation is part of setting it.
    Not when the instruction already gave the switch a value, nor when a word of the switch is
    said negated ("set the alarm hour to 6 but leave the alarm off")."""
    for _feature, steps in view.model.features.items():
        for index, step in enumerate(steps):
            if step.variable not in goal or view.infos[step.variable].role != "setting":
                continue
            for later in steps[index + 1 :]:
                info = view.infos.get(later.variable or "")
                if info is None or info.role != "switch" or info.name in goal:
                    continue
                effects = [effect for _a, effect in step_effects(later)]
                if (
                    effects
                    and all(isinstance(e, GoTo) and str(e.to) == str(info.on) for e in effects)
                    and not _said_negated(text, info)
                ):
                    goal[info.name] = info.on


def gated_switches(view: Model, text: Text, goal: Goal) -> None:
    """A setting that exists or moves only while a switch is on (a temperature kept only with
    the HEATER on; ▲ / ▼ refused while HEAT is off) implies that switch on: "heat the bath to
    60 degrees" asks for the heater. Not when the instruction names the switch, nor when the
    panel starts with it on, nor when a word of the switch is said negated ("switch off the
    heat, 42 degrees is fine": a word too general for :func:`switches` to read, still no)."""
    for name in list(goal):
        info = view.infos.get(name)
        if info is None or info.role != "setting":
            continue
        for gate in _gates(view, info):
            if gate.name in goal or str(_initial(gate)) == str(gate.on):
                continue
            if not _said_negated(text, gate):
                goal[gate.name] = gate.on


def _said_negated(text: Text, info: VarInfo) -> bool:
    """A word of the switch, or one it begins ("heat" of HEATER), stands in the instruction
    with a negation around it ("no heating", "don't heat it")."""
    own, mine = own_stems(info), own_concepts(info)

    def of_it(k: int) -> bool:
        word = text.stems[k]
        if word in own or text.concepts[k] in mine:
            return True
        return len(word) >= 4 and any(o.startswith(word) or word.startswith(o) for o in own)

    return any(of_it(k) and negative_around(text, k) for k in range(len(text.tokens)))


def _gates(view: Model, info: VarInfo) -> list[VarInfo]:
    """The switches (not power) whose off state leaves ``info`` unset or its keys refused."""
    found: list[VarInfo] = []
    parent = view.infos.get(info.var.depends_on or "")
    cases = set(getattr(info.var, "cases", None) or {})
    if parent is not None and parent.role == "switch" and cases == {str(parent.on)}:
        found.append(parent)
    own = {
        action
        for steps in view.model.features.values()
        for step in steps
        if step.variable == info.name
        for action, _effect in step_effects(step)
    }
    for guard in view.model.guards:
        if len(guard.when) != 1 or not own:
            continue
        ((switch_name, state),) = guard.when.items()
        gate = view.infos.get(switch_name)
        if gate is None or gate.role != "switch" or str(state) != str(gate.off):
            continue
        if not own & set(guard.only) and gate not in found:
            found.append(gate)
    return found


def _initial(info: VarInfo) -> Any:
    """The value the panel shows before anything is pressed."""
    var = info.var
    initial = getattr(var, "initial", None)
    if initial is None and isinstance(var, DiscreteVariable) and var.values:
        return var.values[0]
    return initial
