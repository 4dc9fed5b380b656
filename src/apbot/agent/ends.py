"""A setting believed to wrap round that stopped at its end instead.

A knob or key the belief says goes round from its last value to its first (a discrete list
wraps unless the manual says otherwise) left the display exactly as it was at that end: the
setting stops there. Without this the planner keeps taking the short way round the end —
a programme knob at OFF turned anticlockwise towards STORE — and the same key does nothing
again and again. A clamp is one data edit (``wrap: false``); the planner then goes the long
way, which reaches the value whether or not the guess was right.
"""

from __future__ import annotations

from apbot.agent.model_edits import RepairError, _dump, _rebuild
from apbot.agent.session import Executed, Session
from apbot.model.schema import ApplianceModel

__all__ = ["stopped_at_end"]


def stopped_at_end(session: Session, done: Executed) -> bool:
    """``done`` was to wrap its setting round from one end to the other and the display did
    not change at all: the setting clamps at its ends (once per setting). True when the
    belief changed."""
    name = done.variable
    if name is None or done.pointer is None or done.state_before is None:
        return False
    if not done.unchanged or done.refused or done.surprises.get(name) is None:
        return False
    model = session.belief.model
    spec = model.variables.get(name)
    if spec is None or not spec.wrap:
        return False
    effect = session.effect(done.pointer, done.action.name)
    if effect not in ("next", "prev"):
        return False
    before = session.belief.compiled.value(done.state_before, name)
    values = session.domain_values(name)
    if len(values) < 3 or before not in values:
        return False
    end = values[-1] if effect == "next" else values[0]
    if before != end or done.predicted != (values[0] if effect == "next" else values[-1]):
        return False  # not a press across the end
    if not session.budget.once("end", name):
        return False
    try:
        new = stop_at_ends(model, name)
    except RepairError as exc:
        session.episode.log("repair", f"could not make {name} stop at its ends: {exc}")
        return False
    note = f"{name} stops at its ends ({done.action.name} did nothing at {before})"
    session.adopt(new, note, session.belief.pointer())
    session.belief.set_value(name, before)
    return True


def stop_at_ends(model: ApplianceModel, name: str) -> ApplianceModel:
    """``name`` clamps at its first and last values instead of wrapping round."""
    data = _dump(model)
    data["variables"][name]["wrap"] = False
    return _rebuild(data)
