"""The case a value implies: a setting that depends on a mode ("MIST 1-3 only in MANUAL", a melt
temperature free only in MANUAL, fixed in each automatic type) and is given a value only one of
the mode's cases admits can only be set in that case, so the goal holds the mode too.

Nothing is guessed: when two cases admit the value, or the mode starts in the one case anyway
(what the panel shows before anything is pressed), the mode is left as the user left it; so it
is when the case is named for the setting itself (MODE: POWER / TEMPERATURE chooses which of the
two the keys adjust — saying the temperature is choosing it, not a programme)."""

from __future__ import annotations

from typing import Any

from apbot.model.domain import build_domain
from apbot.model.schema import DiscreteVariable
from apbot.read.goal_values import name_words
from apbot.read.goal_view import Goal, Model, own_stems
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
