"""A setting whose range differs per choice of another setting, printed one line per choice.

Manuals list an amount's limits under the sentence about its knob or keys, a line per mode or
process led by the choice's name: "MMA  20 - 160 A" / "TIG  10 - 200 A" / "MIG  40 - 180 A",
"Bass  30 - 60 %" / "Treble  20 - 80 %". The builder reads the first line as the amount's only
range, and the other choices' amounts are then out of reach. When every choice of a discrete
setting leads a line of its own with a range, within a few sentences of each other, and one of
them is the range the amount was read with, the amount takes one case per choice. The choices'
start values come from a line that names each with a figure after a sentence about starting or
being set to ("each time you change the process, the current is set to that process's starting
value:" / "MMA 90 A   TIG 80 A   MIG 100 A").
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import tidy_number
from apbot.read.build import Builder
from apbot.read.values import NUM, number

_NEAR = 3  # the choices' lines stand within this many sentences of each other
_DASH = r"\s*(?:–|—|-|to|\.\.\.|…)\s*"
_START_RE = re.compile(
    r"\b(?:start(?:s|ing)?\s+(?:value|at|from)|(?:is|are)\s+set\s+to|returns?\s+to|default)\b",
    re.I,
)
# settings that are never an amount's selector
_NOT_SELECTORS = {"power", "lock", "child_lock", "running"}


def _led_range(text: str, value: str) -> tuple[float, float] | None:
    """(low, high) when the line is led by the choice's name and then gives a range."""
    m = re.match(
        rf"\W*{re.escape(value)}\s*[:=]?\s+([-+]?{NUM})\s*[^\d\s-]{{0,3}}{_DASH}([-+]?{NUM})(?![\d:])",
        text,
        re.I,
    )
    if m is None:
        return None
    lo, hi = number(m.group(1).lstrip("+")), number(m.group(2).lstrip("+"))
    if lo is None or hi is None or not lo < hi:
        return None
    return lo, hi


def choice_ranges(b: Builder) -> None:
    """Give a numeric setting one case per choice of a discrete setting, when the manual prints
    a line with a range for each choice beside the range the setting was read with."""
    units = b.manual.units
    for selector, sspec in list(b.variables.items()):
        values = [str(v) for v in sspec.get("values") or []]
        if (
            sspec.get("type") != "discrete"
            or sspec.get("depends_on")
            or selector in _NOT_SELECTORS
            or not 2 <= len(values) <= 8
            or {"off", "on"} <= set(values)
        ):
            continue
        found: dict[int, tuple[str, float, float]] = {}
        for index, unit in enumerate(units):
            for value in values:
                led = _led_range(unit.text, value)
                if led is not None:
                    found[index] = (value, *led)
                    break
        for name, spec in b.variables.items():
            if name != selector and spec.get("type") == "numeric" and not spec.get("depends_on"):
                _take(b, name, spec, selector, values, found)


def _take(
    b: Builder,
    name: str,
    spec: dict[str, Any],
    selector: str,
    values: list[str],
    found: dict[int, tuple[str, float, float]],
) -> None:
    """The cases, when a run of lines near the setting's own range covers every choice."""
    ranges = spec.get("ranges") or []
    if len(ranges) != 1:
        return
    lo, hi, step = ranges[0]
    for at, (_, flo, fhi) in found.items():
        if (flo, fhi) != (lo, hi):
            continue
        near = {i: f for i, f in found.items() if abs(i - at) <= _NEAR}
        byval = {
            f[0]: (f[1], f[2]) for _, f in sorted(near.items(), key=lambda x: abs(x[0] - at))[::-1]
        }
        if set(byval) != set(values) or len(set(byval.values())) < 2:
            continue
        cases: dict[str, Any] = {}
        for value in values:
            vlo, vhi = byval[value]
            top = vlo + int((vhi - vlo) / step + 1e-9) * step
            cases[value] = {"ranges": [[tidy_number(vlo), tidy_number(top), tidy_number(step)]]}
        _starts(b, cases)
        for key in ("ranges", "initial"):
            spec.pop(key, None)
        spec["depends_on"] = selector
        spec["cases"] = cases
        shown = ", ".join(
            f"{k} {c['ranges'][0][0]:g}–{c['ranges'][0][1]:g}" for k, c in cases.items()
        )
        b.note(f"variables.{name}.cases", f"one range per {selector}: {shown}", at)
        return


def _starts(b: Builder, cases: dict[str, Any]) -> None:
    """Each choice's start value, from a line naming every choice with a figure in its range
    that follows (or is) a sentence about what the setting starts at or is set to."""
    units = b.manual.units
    for i, unit in enumerate(units):
        said = unit.text if _START_RE.search(unit.text) else ""
        if not said and not (i and _START_RE.search(units[i - 1].text)):
            continue
        figures: dict[str, float] = {}
        for value in cases:
            m = re.search(
                rf"(?<!\w){re.escape(value)}\s*:?\s+([-+]?{NUM})(?![\d.:-])", unit.text, re.I
            )
            figure = number(m.group(1).lstrip("+")) if m else None
            lo, hi, step = cases[value]["ranges"][0]
            if figure is None or not lo <= figure <= hi or (figure - lo) % step:
                break
            figures[value] = figure
        else:
            for value, figure in figures.items():
                cases[value]["initial"] = tidy_number(figure)
            return


# a cell that is one range, its ends maybe signed: "0 ... 10", "-5 ... +5", "20 – 160 A"
_CELL_RANGE_RE = re.compile(
    rf"\s*([-+−]?{NUM})\s*(?:\.\.\.|…|–|—|-|to)\s*([-+−]?{NUM})\s*[A-Za-z%°]{{0,4}}\s*", re.I
)
_START_HEAD_RE = re.compile(r"\b(?:starts?|start(?:ing)?\s+value|default|factory)\b", re.I)


def _signed(text: str) -> float | None:
    sign = -1.0 if text[:1] in "-−" else 1.0
    value = number(text.lstrip("+-−"))
    return None if value is None else sign * value


def _cell_range(cell: str) -> tuple[float, float] | None:
    m = _CELL_RANGE_RE.fullmatch(cell)
    if m is None:
        return None
    lo, hi = _signed(m.group(1)), _signed(m.group(2))
    return (lo, hi) if lo is not None and hi is not None and lo < hi else None


def table_choice_ranges(b: Builder) -> None:
    """A setting a chart per choice names in one column ("| MMA | Arc force | 0 ... 10 | 5 |",
    "ADJ sets" over what the knob does per process) and gives a range for in a column headed
    only "Range": an amount per choice (its start from a "Starts at" / "Default" column), not
    the names of what it does. Choices whose row gives no range ("-") are left out."""
    from apbot.read.cases import _bare_range, _matches  # (cases imports the builder's helpers)
    from apbot.read.cases_tables import _parent_values, _tables

    for header, rows in _tables(b.manual.units):
        ranged = [c for c in range(1, len(header)) if _bare_range(header[c])]
        if len(rows) < 2 or len(ranged) != 1:
            continue
        col = ranged[0]
        found = {}
        for row in rows:
            got = _cell_range(row.cells[col]) if col < len(row.cells) else None
            if got is not None:
                found[row.cells[0]] = (got, row)
        if len(found) < 2:
            continue
        for parent, pspec in b.variables.items():
            pvalues = [str(v) for v in pspec.get("values") or []]
            if pspec.get("type") != "discrete" or not pvalues:
                continue
            if not all(_parent_values(first, pvalues) for first in found):
                continue
            for name, spec in b.variables.items():
                named = [c for c in range(1, col) if _matches(header[c], name, spec)]
                if name == parent or not named or spec.get("type") != "discrete":
                    continue
                if spec.get("depends_on") != parent:
                    continue  # a FAN LOW / HIGH of its own that the chart pairs with each mode
                _as_amount(b, name, spec, parent, header, found, col)
                return


def _as_amount(
    b: Builder,
    name: str,
    spec: dict[str, Any],
    parent: str,
    header: tuple[str, ...],
    found: dict[str, Any],
    col: int,
) -> None:
    from apbot.read.cases_tables import _parent_values

    starts = [c for c in range(1, len(header)) if c != col and _START_HEAD_RE.search(header[c])]
    pvalues = [str(v) for v in b.variables[parent].get("values") or []]
    cases: dict[str, Any] = {}
    for first, ((lo, hi), row) in found.items():
        for value in _parent_values(first, pvalues):
            case: dict[str, Any] = {"ranges": [[tidy_number(lo), tidy_number(hi), 1]]}
            if starts and starts[0] < len(row.cells):
                start = _signed(row.cells[starts[0]].strip())
                if start is not None and lo <= start <= hi and start == int(start):
                    case["initial"] = tidy_number(start)
            cases[value] = case
    for key in ("values", "ranges", "initial", "show"):
        spec.pop(key, None)
    spec["type"] = "numeric"
    spec["depends_on"] = parent
    spec["cases"] = cases
    shown = ", ".join(f"{k} {c['ranges'][0][0]:g}–{c['ranges'][0][1]:g}" for k, c in cases.items())
    first_row = next(iter(found.values()))[1]
    at = next((i for i, u in enumerate(b.manual.units) if u is first_row), None)
    b.note(f"variables.{name}.cases", f"an amount per {parent} (a Range column): {shown}", at)
