"""A setting its own key shows as absent (``--``) right after a programme was chosen.

Many appliances have settings that only some programmes take: a drying time in DRY but not in
AUTO. A reader that missed this believes the setting is always there, and the planner sets it
in whatever programme it passes first. When the setting's own key then brings up its screen
with no value (``TIME --``), the setting does not exist in the programme just chosen (or in
the one it started in, when the agent has chosen none): the
belief makes it depend on that programme, with no case for its current choice and its old
domain for every other one. The planner then chooses another programme first; a walk there
learns the setting's real values in it.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.model_edits import _dump, _rebuild
from apbot.agent.session import MISSING, Executed, Session
from apbot.model.schema import ApplianceModel, DiscreteVariable

__all__ = ["absent_here"]


def absent_here(session: Session, name: str, done: Executed, observed: Any) -> bool:
    """``done`` — a press of ``name``'s own step — showed ``name``'s screen with no value where
    the belief holds one: ``name`` is absent in the programme chosen last (once per setting).
    True when the belief changed."""
    model = session.belief.model
    spec = model.variables.get(name)
    if observed is not None or spec is None or spec.depends_on is not None:
        return False
    if done.variable != name or done.refused or name in session.discovered:
        return False
    if done.seen is None or done.seen.observed(name) is MISSING:
        return False  # not its screen: a dark panel, another setting
    parent = _programme(session, name)
    if parent is None or not session.budget.once("case", f"absent:{name}"):
        return False
    here = str(session.belief.value(parent))
    return session.try_repair(
        lambda: depend_on(model, name, parent, here),
        f"{name} has no value in {parent} {here}",
        session.belief.pointer(),
        refused=f"could not make {name} depend on {parent}",
    )


def _programme(session: Session, name: str) -> str | None:
    """The choice ``name`` may depend on: the one other settings already depend on, else the
    only list of three or more choices the agent has moved from where it started, else the
    only such list at all."""
    model = session.belief.model
    parents = {v.depends_on for v in model.variables.values() if v.depends_on}
    if len(parents) == 1:
        return next(iter(parents))
    choices = [
        n
        for n, s in model.variables.items()
        if n != name
        and isinstance(s, DiscreteVariable)
        and s.depends_on is None
        and len(s.values or ()) >= 3
    ]
    moved = [n for n in choices if session.belief.value(n) != session.belief.initial_value(n)]
    for found in (moved, choices):
        if found:
            return found[0] if len(found) == 1 else None
    return None


def depend_on(model: ApplianceModel, name: str, parent: str, absent: str) -> ApplianceModel:
    """``name`` depends on ``parent``: its own domain in every case but ``absent``."""
    data = _dump(model)
    var = data["variables"][name]
    own = {k: var.pop(k) for k in ("values", "ranges", "initial") if k in var}
    var["depends_on"] = parent
    values = data["variables"][parent]["values"]
    var["cases"] = {str(v): dict(own) for v in values if str(v) != absent}
    return _rebuild(data)
