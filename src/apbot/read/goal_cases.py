"""The mode a setting implies. A setting that depends on a mode ("MIST 1-3 only in MANUAL", a melt
temperature free only in MANUAL, fixed in each automatic type) and is given a value only one of
the mode's cases admits can only be set in that case, so the goal holds the mode too; so does a
setting whose every procedure first puts a mode to one value (CONVECTION, then the temperature
typed: the convection temperature is set in the convection mode only).

Nothing is guessed: when two cases admit the value, or the mode starts in the one case anyway
(what the panel shows before anything is pressed), the mode is left as the user left it; so it
is when the case is named for the setting itself (MODE: POWER / TEMPERATURE chooses which of the
two the keys adjust — saying the temperature is choosing it, not a programme)."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import DiscreteVariable, GoTo
from apbot.read.goal_values import name_words
from apbot.read.goal_view import Goal, Model, own_stems, step_effects
from apbot.read.goal_vocab import stem


def implied_cases(view: Model, goal: Goal) -> None:
    """Set the mode of each goal setting whose value only one case of that mode admits."""
    for name in list(goal):
        var = view.infos[name].var
        parent = var.depends_on
        if not parent or not var.cases or parent in goal or parent not in view.infos:
            continue
        mode = view.infos[parent]
        if mode.role != "setting" or not isinstance(mode.var, DiscreteVariable):
            continue
        admitting = [
            case for case in mode.values if _admits(var, var.cases.get(str(case)), goal[name])
        ]
        if len(admitting) != 1 or len(mode.values) < 2:
            continue
        if str(admitting[0]) == str(_starts_at(mode.var)):
            continue  # the panel is in that case before anything is pressed
        if {stem(w) for w in name_words(str(admitting[0]))} & own_stems(view.infos[name]):
            continue  # the TEMPERATURE mode of the temperature: a choice of what to adjust
        goal[parent] = admitting[0]


def entry_modes(view: Model, goal: Goal) -> None:
    """Set the mode each goal setting's procedures all enter first (a key that goes to one
    value of a mode, then the setting's own step), unless the panel starts in it."""
    for name in list(goal):
        if view.infos[name].role != "setting":
            continue
        common: set[tuple[str, str]] | None = None
        for steps in view.model.features.values():
            for index, step in enumerate(steps):
                if step.variable != name:
                    continue
                entered = _entered(steps[:index], name)
                common = entered if common is None else common & entered
        for mode_name, value in sorted(common or ()):
            mode = view.infos.get(mode_name)
            if mode is None or mode_name in goal or mode.role != "setting":
                continue
            if view.infos[name].var.depends_on == mode_name:
                continue  # a case of that mode: implied_cases has judged it
            if not isinstance(mode.var, DiscreteVariable):
                continue
            chosen = next((v for v in mode.values if str(v) == value), None)
            if chosen is not None and str(chosen) != str(_starts_at(mode.var)):
                goal[mode_name] = chosen


def _entered(earlier: list[Any], name: str) -> set[tuple[str, str]]:
    """(mode, value) of each earlier step whose keys all put a mode to the same one value."""
    found: set[tuple[str, str]] = set()
    for step in earlier:
        if step.variable in (None, name):
            continue
        effects = [effect for _action, effect in step_effects(step)]
        targets = {str(e.to) for e in effects if isinstance(e, GoTo)}
        if effects and len(targets) == 1 and all(isinstance(e, GoTo) for e in effects):
            found.add((step.variable, targets.pop()))
    return found


def _admits(var: Any, spec: Any, value: Any) -> bool:
    if spec is None:
        return False
    try:
        values = build_domain(var, spec).values
    except ValueError:
        return False
    return any(str(v) == str(value) or _same_number(v, value) for v in values)


def _same_number(a: Any, b: Any) -> bool:
    try:
        return abs(float(a) - float(b)) < 1e-9
    except (TypeError, ValueError):
        return False


def _starts_at(var: DiscreteVariable) -> Any:
    initial = getattr(var, "initial", None)
    if initial is not None:
        return initial
    return var.values[0] if var.values else None
