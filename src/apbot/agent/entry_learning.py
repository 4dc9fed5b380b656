"""Learning how a keypad's digits become a value: the entry format, from what the display
showed as they were typed.

A manual says "type the cooking time" and the reader guesses how digits are read (``mm:ss``
on a microwave, ``h:mm`` for a delay); the display then shows what the keypad made of them.
Split from :mod:`apbot.agent.walk_learning` (a walk teaches values; this teaches typing).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from apbot.agent.quantities import magnitude
from apbot.agent.repair import RepairError, set_entry_format
from apbot.agent.session import MISSING, Executed, Session
from apbot.model.effects import parse_entry, type_digit
from apbot.model.schema import TimeVariable
from apbot.model.variables import Entry

__all__ = ["learn_entry_format"]


def learn_entry_format(
    session: Session,
    name: str,
    last: Executed,
    observed: Any,
    unchanged: bool,
    typed: Sequence[Executed] = (),
) -> bool:
    """Digits typed gave another value than the belief's entry format reads: find the
    format that reads them as shown (``minutes`` for what is really ``mm:ss``). A value
    that did not change at all fits every format that reads the digits as no value of the
    setting (typing 5 on an ``mm:ss`` keypad for a setting in whole minutes). When no format
    reads the last digits as shown, the digits of the entry (``typed``, in order) are replayed
    one by one: a keypad that keeps two digits (1, 3, 9 shows 39) or ignores a digit past its
    range (4, 0, 0 shows 40 where it takes up to 240 minutes) says so."""
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
    fitting: list[Entry] = [
        entry.model_copy(update={"format": f}) for f in _entry_formats(spec) if fits(f)
    ][:1]
    if not fitting:  # the whole entry as typed, digit by digit
        fitting = [e for e in _entries(spec, entry) if _replays(session, name, typed, e)]
    if not fitting or not session.budget.once("entry", name):
        return False
    for found in fitting:  # the first that can still type every value the belief has
        try:
            new = set_entry_format(
                session.belief.model, name, found.format, found.max_digits, found.overflow
            )
            break
        except RepairError as exc:
            problem = exc
    else:
        session.episode.log("repair", f"could not repair {name}'s entry: {problem}")
        return False
    kept = f", {found.max_digits} digits kept" if found.max_digits != entry.max_digits else ""
    session.adopt(
        new,
        f"{name}: digits are read as {found.format}{kept} (typed {last.buffer}, shown {observed})",
        last.pointer,
    )
    session.belief.set_value(name, observed)
    return True


def _entries(spec: Any, entry: Entry) -> list[Entry]:
    """Every way a keypad could read digits: each format, keeping the digits the belief says
    (or two to four), a digit past them shifting the oldest out or ignored."""
    found: list[Entry] = []
    for fmt in _entry_formats(spec):
        for digits in dict.fromkeys((entry.max_digits, 2, 3, 4)):
            for overflow in ("shift", "ignore"):
                found.append(
                    entry.model_copy(
                        update={"format": fmt, "max_digits": digits, "overflow": overflow}
                    )
                )
    return found


def _replays(session: Session, name: str, typed: Sequence[Executed], entry: Entry) -> bool:
    """Whether ``entry`` reads the digits of one fresh entry as the display showed each of
    them. As on the appliance, digits that read as no value the setting has leave the value
    as it was (typing past a keypad's range): the display may then not change at all. At
    least two shown values must be read, one of them after a digit the format alone missed."""
    actions = session.belief.model.actions
    spec = session.belief.model.variables[name]
    possible = set(session.magnitudes(name))
    presses = [e for e in typed if e.buffer]
    if len(presses) < 2 or len(presses[0].buffer) != 1:
        return False  # not the digits of one entry from its start
    buffer, value, read = "", None, 0
    for press in presses:
        digit = actions[press.action.name].digit if press.action.name in actions else None
        if digit is None:
            return False
        buffer = type_digit(buffer, str(digit), entry)
        reading = parse_entry(buffer, entry)
        if reading is not None and reading in possible:
            value = reading
        shown = press.observed(name)
        number = None if shown is MISSING or shown is None else magnitude(spec, shown)
        if number is None:
            continue
        if number != value:
            return False
        read += 1
    return read >= 2


def _entry_formats(spec: Any) -> list[str]:
    """The keypad formats a variable could use, the one matching its display first."""
    if not isinstance(spec, TimeVariable):
        return ["number"]
    order = ["mm:ss", "hh:mm", "h:mm", "hh:mm:ss", "minutes", "seconds"]
    preferred = {"mm:ss": "mm:ss", "hh:mm": "hh:mm", "h:mm": "h:mm", "min": "minutes"}
    first = preferred.get(spec.format)
    return ([first] if first else []) + [f for f in order if f != first]
