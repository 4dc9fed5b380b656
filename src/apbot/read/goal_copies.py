"""Two settings with the same values, one the other's pending choice: a knob that only
highlights a course (SEL) and a push that confirms it (COURSE). The user names the course
to run; the one the rest of the panel is kept per (its DRY+ time depends on COURSE) is the
one meant, not the highlight that leads to it."""

from __future__ import annotations

from apbot.model.schema import DiscreteVariable
from apbot.read.goal_view import Goal, Model


def confirmed_choices(view: Model, goal: Goal, where: dict[str, int]) -> None:
    """Move a value from a setting no other depends on to the one setting with exactly its
    values that others depend on."""
    depended = {getattr(info.var, "depends_on", None) for info in view.infos.values()} - {None}
    for name in list(goal):
        info = view.infos.get(name)
        if info is None or name in depended or not isinstance(info.var, DiscreteVariable):
            continue
        values = {str(v) for v in info.values}
        if len(values) < 3:
            continue
        twins = [
            other
            for other, o in view.infos.items()
            if other != name
            and other in depended
            and other not in goal
            and isinstance(o.var, DiscreteVariable)
            and {str(v) for v in o.values} == values
        ]
        if len(twins) == 1:
            goal[twins[0]] = goal.pop(name)
            if name in where:
                where[twins[0]] = where.pop(name)
