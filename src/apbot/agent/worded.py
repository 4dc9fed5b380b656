"""A numeric setting whose panel names some of its positions in words.

A spin speed that goes 1400, 1200, …, 400, then "no spin" and "rinse hold"; a wash temperature
that goes down to "cold". The manual's table gives the numbers, the reader makes a numeric
setting, and the walk finds positions printed as words where a number should be: text the
belief cannot read, between the numbers it reads. The positions are choices, numbers and words
alike — the setting becomes a list of them (the numbers as the panel prints them), so the walk
can learn their order and the planner count every press.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

from apbot.agent.infer import Dark, Unread
from apbot.agent.reader import DisplayReader
from apbot.agent.repair import RepairError, _dump, _rebuild
from apbot.model.domain import all_values
from apbot.model.schema import ApplianceModel, NumericVariable

WORDS = re.compile(r"[^\W\d_]+(?:[ '/-][^\W\d_]+)*")
"""Words of letters only, one or a few (``no spin``, ``rinse hold``, ``chef's``): a name."""


def worded_values(spec: NumericVariable, name: str, texts: Sequence[str]) -> list[str] | None:
    """The words the display printed in place of a number (``SPIN no spin`` → ``no spin``):
    each text is the setting's label (or its template's fixed start, or that cut short to a
    word of three letters or more) followed by words of letters only. None unless every
    text is.

    >>> spin = NumericVariable(type="numeric", ranges=[(400, 1400, 200)], label="SPIN")
    >>> worded_values(spin, "spin", ["SPIN no spin", "SPIN  rinse hold"])
    ['no spin', 'rinse hold']
    >>> worded_values(spin, "spin", ["SPIN 1600"]) is None
    True
    >>> temp = NumericVariable(type="numeric", ranges=[(20, 60, 10)], label="TEMPERATURE")
    >>> worded_values(temp, "temp", ["TEMP cold"])
    ['cold']
    """
    label = spec.display_label(name)
    prefix = label
    if isinstance(spec.show, str) and "{value}" in spec.show:
        prefix = spec.show.split("{value}")[0].replace("{label}", label).strip()
    words: list[str] = []
    for text in texts:
        text = " ".join(text.split())
        start = text.split(" ")[0]
        if len(start) >= 3 and prefix.casefold().startswith(start.casefold()):
            pass  # the label cut short (TEMP for TEMPERATURE)
        elif prefix and text.casefold().startswith(prefix.casefold() + " "):
            start = prefix
        else:
            return None
        rest = text[len(start) :].strip()
        if not WORDS.fullmatch(rest):
            return None
        if rest not in words:
            words.append(rest)
    return words or None


def as_choices(model: ApplianceModel, name: str, words: Sequence[str]) -> ApplianceModel:
    """``name`` as a list of choices: its numbers (as printed, without a unit) then ``words``.
    Only a setting with one domain (no programme cases, no keypad entry)."""
    spec = model.variables[name]
    if not isinstance(spec, NumericVariable) or spec.cases or spec.entry or spec.ranges is None:
        raise RepairError(f"{name} is not a plain numeric setting")
    data = _dump(model)
    var = data["variables"][name]
    numbers = [_printed(v) for v in all_values(spec)]
    values = numbers + [w for w in words if w not in numbers]
    new: dict[str, Any] = {"type": "discrete", "values": values}
    for key in ("label", "show", "visible", "depends_on", "wrap"):
        if key in var:
            new[key] = var[key]
    if "initial" in var and _printed(var["initial"]) in values:
        new["initial"] = _printed(var["initial"])
    data["variables"][name] = new
    return _rebuild(data)


def reads_all(model: ApplianceModel, name: str, texts: Sequence[str]) -> bool:
    """Whether ``model`` reads every text as a value of ``name``."""
    reader = DisplayReader(model)
    return all(
        any(h.screen.variable == name and name in h.values for h in reader.read(t).hypotheses)
        for t in texts
    )


def as_text(trace: list[Any]) -> list[Any]:
    """A walk's values as the choices they now are (numbers as printed)."""
    return [v if isinstance(v, Dark | Unread) else _printed(v) for v in trace]


def _printed(value: Any) -> str:
    """A number as a panel prints it (``1200``, ``0.5``)."""
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    return str(value)
