"""A time the display prints as ``a:bb`` read in the wrong style: minutes:seconds for hours:minutes.

``0:40`` is forty seconds on a microwave and forty minutes on a bottle dryer; a manual's own
examples rarely say which, and the reader guesses. A walk read in the wrong style is a walk of
values sixty times too small (or large), and the goal is then "not a value the model knows".
When the goal's time is not among the values a walk showed but the same texts, read in the
other style, show it, the display prints that style: the belief's format is changed and the
walk's values are scaled to it before anything is learnt from them.
"""

from __future__ import annotations

from typing import Any

from apbot.agent.infer import Dark
from apbot.agent.model_edits import RepairError, _dump, _rebuild
from apbot.agent.quantities import canonical, loose, magnitude
from apbot.agent.session import Session
from apbot.model.schema import ApplianceModel, TimeVariable

__all__ = ["restyle_walk"]

# two-field styles and the style that reads the same digits sixty times larger
_LARGER = {"mm:ss": "h:mm"}
_SMALLER = {"h:mm": "mm:ss", "hh:mm": "mm:ss"}


def restyle_walk(
    session: Session, name: str, forward: list[Any], backward: list[Any] | None
) -> tuple[list[Any], list[Any] | None]:
    """A walk's values (``forward``, then ``backward``; read under the belief's format) read
    in the other two-field style, where only that reading shows the goal's time (once per
    setting); else as they were."""
    walks = (forward, backward)
    spec = session.belief.model.variables.get(name)
    goal = session.context.goal.get(name)
    if not isinstance(spec, TimeVariable) or goal is None:
        return forward, backward
    wanted = magnitude(spec, loose(spec, goal))
    if wanted is None:
        return forward, backward
    seen = [
        m
        for walk in walks
        for v in walk or ()
        if not isinstance(v, Dark) and (m := magnitude(spec, v)) is not None
    ]
    if not seen or wanted in seen:
        return forward, backward
    if spec.format in _LARGER and wanted / 60 in seen and max(seen) < 3600:
        style, factor = _LARGER[spec.format], 60.0
    elif spec.format in _SMALLER and wanted * 60 in seen:
        style, factor = _SMALLER[spec.format], 1 / 60
    else:
        return forward, backward
    if not session.budget.once("template", f"{name}:style"):
        return forward, backward
    try:
        new = restyled(session.belief.model, name, style)
    except RepairError as exc:
        session.episode.log("repair", f"could not read {name} as {style}: {exc}")
        return forward, backward
    session.adopt(new, f"{name} is shown as {style}, not {spec.format}", session.belief.pointer())

    def scaled(value: Any) -> Any:
        number = magnitude(spec, value)
        return value if number is None else canonical(spec, number * factor)

    return [scaled(v) for v in forward], None if backward is None else [scaled(v) for v in backward]


def restyled(model: ApplianceModel, name: str, style: str) -> ApplianceModel:
    """``name``'s display (and keypad) style is ``style``."""
    data = _dump(model)
    data["variables"][name]["format"] = style
    return _rebuild(data)
