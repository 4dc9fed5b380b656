"""A setting whose range depends on the unit a selector chooses.

A panel that shows a temperature in °C or °F, or a water hardness in °dH, ppm or gpg, keeps
the setting in the chosen unit, and the manual prints one range per unit side by side: "In °C:
35 to 48 degrees. In °F: 95 to 118 degrees.", "35 - 48 °C / 95 - 118 °F", or one line per
unit ("°dH: 1 to 40, in steps of 1" / "ppm: 20 to 700, in steps of 10"). The builder reads one
of those ranges as the setting's only range. When a discrete setting's values are all units
and the manual gives, close together, a range for each of them, one of which is the range the
setting was read with, the setting takes one case per unit on that selector — so a goal said
in the other unit ("110 °F") is a value the setting has, not a number to convert.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import tidy_number
from apbot.read.build import Builder
from apbot.read.goal_unit_cases import UNIT_WORDS
from apbot.read.value_steps import find_step
from apbot.read.values import NUM, number

_NEAR = 3  # the ranges of one setting per unit stand within this many sentences or rows
_SPELLED = {"c": r"celsius|centigrade", "f": r"fahrenheit"}  # a scale said by its letter


def _unit_pattern(value: str, shown: str | None) -> str | None:
    """How a unit value is written in the manual ("°C", "degrees Celsius", "°dH", "ppm"), or
    None when the value is not a unit."""
    names = {str(x).casefold().lstrip("°").strip() for x in (value, shown) if x}
    names = {n for n in names if n}
    if not names or not any(n in UNIT_WORDS for n in names):
        return None
    short = {n[0] for n in names if n in ("c", "celsius", "f", "fahrenheit")}
    parts = [rf"(?:°\s?|degrees?\s+){s}(?![a-z])" for s in short]
    parts += [rf"(?:degrees?\s+)?(?:{_SPELLED[s]})\b" for s in short]
    parts += [rf"°?{re.escape(n)}(?![a-z])" for n in names if len(n) > 1 and n not in _SPELLED]
    return "|".join(parts) if parts else None


_DASH = r"\s*(?:–|—|-|to)\s*"


def _tagged_ranges(text: str, units: dict[str, str]) -> list[tuple[str, float, float, int, int]]:
    """(unit value, low, high, start, end) for each range in ``text`` that a unit names: after
    its high end ("95 - 118 °F"), or before it with a colon ("In °F: 95 to 118")."""
    out = []
    any_unit = "|".join(f"(?:{p})" for p in units.values())
    for m in re.finditer(
        rf"(?<![\w.:])({NUM})\s*(?:{any_unit})?{_DASH}({NUM})(?![\w:.]|[.,]\d)", text, re.I
    ):
        lo, hi = number(m.group(1)), number(m.group(2))
        if lo is None or hi is None or not lo < hi:
            continue
        after = text[m.end() : m.end() + 24]
        before = text[max(0, m.start() - 40) : m.start()]
        tag = None
        for value, pattern in units.items():
            if re.match(rf"\s*(?:{pattern})", after, re.I):
                tag = value
                break
        if tag is None:
            for value, pattern in units.items():
                if re.search(rf"(?:{pattern})\s*:\s*$", before, re.I):
                    tag = value
                    break
        if tag is not None:
            out.append((tag, lo, hi, m.start(), m.end()))
    return out


def unit_ranges(b: Builder) -> None:
    """Give a numeric setting one case per unit of a unit selector, when the manual prints a
    range for every unit next to the range the setting was read with."""
    for selector, sspec in b.variables.items():
        values = sspec.get("values") or []
        if sspec.get("type") != "discrete" or sspec.get("depends_on") or not 2 <= len(values) <= 4:
            continue
        shown = sspec.get("show")
        shows: dict[str, Any] = shown if isinstance(shown, dict) else {}
        patterns = {v: _unit_pattern(str(v), shows.get(v)) for v in values}
        if not all(patterns.values()):
            continue
        units = {v: p for v, p in patterns.items() if p}
        found: list[tuple[int, str, float, float, float | None]] = []
        for index, unit in enumerate(b.manual.units):
            tagged = _tagged_ranges(unit.text, units)
            for k, (tag, lo, hi, _start, end) in enumerate(tagged):
                stop = tagged[k + 1][3] if k + 1 < len(tagged) else len(unit.text)
                step = find_step(re.split(r"[;.](?:\s|$)", unit.text[end:stop])[0])
                found.append((index, tag, lo, hi, step[0] if step else None))
        taken = False
        for name, spec in b.variables.items():
            if name != selector and spec.get("type") == "numeric" and not spec.get("depends_on"):
                taken |= _take_cases(b, name, spec, selector, values, found)
        if taken and not shows:
            _printed(b, selector, sspec)


def _printed(b: Builder, selector: str, spec: dict[str, Any]) -> None:
    """A unit is shown as the manual prints it ("°C", "°dH"), whatever case the read value
    has, so that the display tells which unit the setting is kept in."""
    text = "\n".join(u.text for u in b.manual.units)
    show = {}
    for value in spec["values"]:
        spellings = re.findall(rf"(?<![\w°]){re.escape(str(value))}(?![\w])", text, re.I)
        if not spellings:
            return
        show[value] = max(set(spellings), key=spellings.count)
    spec["show"] = show
    b.note(f"variables.{selector}.show", "each unit shown as the manual prints it")


def _take_cases(
    b: Builder,
    name: str,
    spec: dict[str, Any],
    selector: str,
    values: list[str],
    found: list[tuple[int, str, float, float, float | None]],
) -> bool:
    """Of the places that give a range per unit beside this setting's range, the one that
    states the most steps (a specification table gives the ends, the setting's own section
    the steps too)."""
    ranges = spec.get("ranges") or []
    if len(ranges) != 1:
        return False
    lo, hi, step = ranges[0]
    best: tuple[int, int, dict[str, Any]] | None = None
    for at, tag, flo, fhi, _ in found:
        if (flo, fhi) != (lo, hi):
            continue
        near = [f for f in found if abs(f[0] - at) <= _NEAR]
        cases: dict[str, Any] = {}
        told = 0
        for value in values:
            mine = sorted((f for f in near if f[1] == value), key=lambda f: abs(f[0] - at))
            if not mine:
                break
            _, _, vlo, vhi, vstep = mine[0]
            told += vstep is not None
            st = vstep or step
            top = vlo + int((vhi - vlo) / st + 1e-9) * st
            cases[value] = {"ranges": [[tidy_number(vlo), tidy_number(top), tidy_number(st)]]}
            if value == tag and "initial" in spec:
                cases[value]["initial"] = spec["initial"]
        else:
            if len({(c["ranges"][0][0], c["ranges"][0][1]) for c in cases.values()}) < 2:
                continue  # the same numbers for every unit: nothing depends on the unit
            if best is None or told > best[1]:
                best = (at, told, cases)
    if best is None:
        return False
    at, _, cases = best
    _starts(b, cases)
    for key in ("ranges", "initial", "unit"):
        spec.pop(key, None)
    spec["depends_on"] = selector
    spec["cases"] = cases
    shown = ", ".join(f"{k} {c['ranges'][0][0]:g}–{c['ranges'][0][1]:g}" for k, c in cases.items())
    b.note(f"variables.{name}.cases", f"one range per unit: {shown}", at)
    return True


# the value a setting starts at, or returns to when the unit changes: "(factory value 270
# ppm)", "resets the temperature to the start value of the new unit: 40 °C, or 104 °F"
_START_RE = re.compile(
    r"\b(?:factory|default|start(?:s|ing)?\s+(?:value|again|at)|returns?\s+to|resets?)\b", re.I
)


def _starts(b: Builder, cases: dict[str, Any]) -> None:
    """Each unit's starting value, where the manual names one in that unit inside the case's
    range (a unit change loads it)."""
    patterns = {v: _unit_pattern(v, None) for v in cases}
    for unit in b.manual.units:
        m = _START_RE.search(unit.text)
        if m is None:
            continue
        rest = unit.text[m.start() :]
        for value, case in cases.items():
            pattern = patterns[value]
            if "initial" in case or pattern is None:
                continue
            lo, hi, step = case["ranges"][0]
            for said in re.finditer(rf"(?<![\w.])({NUM})\s*(?:{pattern})", rest, re.I):
                figure = number(said.group(1))
                if figure is not None and lo <= figure <= hi and not (figure - lo) % step:
                    case["initial"] = tidy_number(figure)
                    break
