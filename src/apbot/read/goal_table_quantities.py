"""A numbered setting named by the quantity the manual's chart gives each number.

A chart of the kind "Rate key   Speed" lists a unitless setting's numbers beside what each one
means ("4   16 × sidereal", "8   2° per second"): people say the quantity, not the key — "slew
at sixteen times sidereal", "move at two degrees a second". The sentence is rewritten to the
setting's name and number ("slew rate 4") before it is read, so the quantity's words
("sidereal") do not name another setting's value either.

Only a chart of three or more rows in a row, each opening with one of the setting's numbers
followed by a cell that opens with a figure and a unit's words, and only a setting whose numbers
hold every row's (where two settings could, the one whose words stand in the lines above the
chart). The figure and every unit word must be said, in order ("times the sidereal rate").
"""

from __future__ import annotations

import re

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable
from apbot.model.values import words_to_number
from apbot.read.goal_view import Model
from apbot.read.goal_vocab import stem

_ROW = re.compile(r"^\s*\|?\s*(\d{1,3})\s*(?:\||\s{2,}|\t)\s*(\d+(?:\.\d+)?)\s*([^|]*)")
_CELL_END = re.compile(r"\s{2,}|\t|\|")
_UNIT_SIGNS = {"×": "times", "°": "degree", "%": "percent"}
_SAME = {  # the ways a unit word is said
    "times": r"(?:times|×|x)",
    "degree": r"(?:degrees?|°|deg)",
    "percent": r"(?:percent|per\s+cent|%)",
    "per": r"(?:per|a|an|each|every)",
}
_MIN_ROWS = 3
_NUMBER = r"(\d+(?:\.\d+)?|(?:[a-z]+[\s-]+){0,3}?[a-z]+)"
_ABOVE = 6
"""Lines above a chart searched for the setting's words, where two settings could own it."""


def _unit_words(cell: str) -> list[str]:
    """The unit of a cell after its figure ("× sidereal" -> times, sidereal): signs spelled,
    brackets ("(max.)") dropped, words singular."""
    text = re.sub(r"\([^)]*\)", " ", _CELL_END.split(cell.strip())[0])
    for sign, word in _UNIT_SIGNS.items():
        text = text.replace(sign, f" {word} ")
    words = re.findall(r"[a-z]+", text.casefold())
    return [w[:-1] if w.endswith("s") and len(w) > 3 else w for w in words]


def _charts(view: Model) -> list[tuple[int, list[tuple[int, float, list[str]]]]]:
    """(first line, rows (number, figure, unit words)) of each run of chart rows."""
    charts: list[tuple[int, list[tuple[int, float, list[str]]]]] = []
    current: list[tuple[int, float, list[str]]] = []
    start = 0
    for index, line in enumerate((*view.manual_lines, "")):
        m = _ROW.match(line)
        unit = _unit_words(m[3]) if m else []
        if m and unit and len(unit) <= 4:
            if not current:
                start = index
            current.append((int(m[1]), float(m[2]), unit))
            continue
        if len(current) >= _MIN_ROWS:
            charts.append((start, current))
        current = []
    return charts


def _owner(view: Model, start: int, numbers: set[int]) -> str | None:
    """The one unitless whole-number setting holding every number, else the one of those
    whose words stand in the lines above the chart."""
    owners = [
        name
        for name, info in view.infos.items()
        if info.role == "setting"
        and isinstance(info.var, NumericVariable)
        and not info.var.unit
        and numbers <= {int(float(v)) for v in all_values(info.var) if float(v).is_integer()}
    ]
    if len(owners) <= 1:
        return owners[0] if owners else None
    heads = [x for x in view.manual_lines[max(0, start - 3) : start] if re.search("[a-z]", x)]
    if heads:  # the chart's own heading over the numbers ("Rate key   Speed"): its first cell
        first = _CELL_END.split(heads[-1].strip())[0]
        words = {stem(w) for w in re.findall(r"[a-z]+", first)}
        named = [n for n in owners if any(w in words for w in view.infos[n].vocab if len(w) > 2)]
        if len(named) == 1:
            return named[0]
    above = " ".join(view.manual_lines[max(0, start - _ABOVE) : start])
    words = {stem(w) for w in re.findall(r"[a-z]+", above)}
    near = [n for n in owners if any(w in words for w in view.infos[n].vocab if len(w) > 2)]
    return near[0] if len(near) == 1 else None


def _unit_pattern(unit: list[str]) -> str:
    parts = [_SAME.get(w, re.escape(w) + "s?") for w in unit]
    return r"\s+(?:the\s+)?".join(parts)


def said_table_quantities(view: Model, instruction: str) -> str:
    """ "sixteen times sidereal" as "slew rate 4" where the manual's chart says 4 is
    16 × sidereal."""
    if not view.manual_lines:
        return instruction
    said = instruction
    for start, rows in _charts(view):
        owner = _owner(view, start, {number for number, _, _ in rows})
        if owner is None:
            continue
        name = owner.replace("_", " ")
        for number, figure, unit in rows:
            pattern = re.compile(
                rf"\b{_NUMBER}\s*{_unit_pattern(unit)}\b(?:\s+{re.escape(name.split()[-1])}\b)?",
                re.IGNORECASE,
            )

            def named(
                m: re.Match[str], figure: float = figure, number: int = number, name: str = name
            ) -> str:
                words = m[1].split()
                for first in range(len(words)):
                    value = words_to_number(" ".join(words[first:]))
                    if value is not None:
                        if value != figure:
                            return m[0]
                        head = " ".join(words[:first])
                        return f"{head}{' ' if head else ''}{name} {number}"
                return m[0]

            said = pattern.sub(named, said)
    return said
