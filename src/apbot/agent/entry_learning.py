"""Learning how a keypad's digits become a value: the entry format, from what the display
showed as they were typed.

A manual says "type the cooking time" and the reader guesses how digits are read (``mm:ss``
on a microwave, ``h:mm`` for a delay); the display then shows what the keypad made of them.
Split from :mod:`apbot.agent.walk_learning` (a walk teaches values; this teaches typing).
"""

from __future__ import annotations

from typing import Any

from apbot.agent.quantities import magnitude
from apbot.agent.repair import RepairError, set_entry_format
from apbot.agent.session import Executed, Session
from apbot.model.effects import parse_entry
from apbot.model.schema import TimeVariable

__all__ = ["learn_entry_format"]


def learn_entry_format(
    session: Session, name: str, last: Executed, observed: Any, unchanged: bool
) -> bool:
    """Digits typed gave another value than the belief's entry format reads: find the
    format that reads them as shown (``minutes`` for what is really ``mm:ss``). A value
    that did not change at all fits every format that reads the digits as no value of the
    setting (typing 5 on an ``mm:ss`` keypad for a setting in whole minutes)."""
    spec = session.belief.model.variables[name]
    entry = getattr(spec, "entry", None)
    shown = magnitude(spec, observed)
    if entry is None or shown is None or not last.buffer:
        return False
    possible = set(session.magnitudes(name))

    def fits(fmt: str) -> bool:
        reading = parse_entry(last.buffer, entry.model_copy(update={"format": fmt}))
        return reading == shown or (unchanged and (reading is None or reading not in possible))

    if fits(entry.format):
        return False  # the format reads the digits as shown: the fault is elsewhere
    fitting = [f for f in _entry_formats(spec) if fits(f)]
    if not fitting or not session.budget.once("entry", name):
        return False
    try:
        new = set_entry_format(session.belief.model, name, fitting[0])
    except RepairError as exc:
        session.episode.log("repair", f"could not repair {name}'s entry: {exc}")
        return False
    session.adopt(
        new,
        f"{name}: digits are read as {fitting[0]} (typed {last.buffer}, shown {observed})",
        last.pointer,
    )
    session.belief.set_value(name, observed)
    return True


def _entry_formats(spec: Any) -> list[str]:
    """The keypad formats a variable could use, the one matching its display first."""
    if not isinstance(spec, TimeVariable):
        return ["number"]
    order = ["mm:ss", "hh:mm", "h:mm", "hh:mm:ss", "minutes", "seconds"]
    preferred = {"mm:ss": "mm:ss", "hh:mm": "hh:mm", "h:mm": "h:mm", "min": "minutes"}
    first = preferred.get(spec.format)
    return ([first] if first else []) + [f for f in order if f != first]
