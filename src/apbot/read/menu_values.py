"""The values of one item of a numbered settings menu (see ``roles_menu``), read from its own
table row or the lines under its heading: a printed run ("1 h - 2 h - 3 h", "1 · 2 · 3 … 9",
"--" for off), a list of names, a range and step, a default; a table headed by an earlier
item's code gives one case per value of that item. Kept apart from ``roles_menu``, which finds
the menu and its keys."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from apbot.model.values import format_hms, parse_hms, tidy_number
from apbot.read.build import Builder
from apbot.read.menu_cells import bare_step, coded_choices, drawn_choice, slashed_words
from apbot.read.roles_common import numeric_list
from apbot.read.roles_lists import list_evidence
from apbot.read.shapes import Evidence
from apbot.read.value_lists import bare_list, find_list
from apbot.read.value_steps import find_initial, find_step
from apbot.read.values import Range, find_ranges, seconds, unit_name

_OFF_MARK = re.compile(r"^(?:--+|-|off|oFF|OFF)(?:\s*\((?:off|none)\))?$", re.IGNORECASE)
_ELLIPSIS = re.compile(r"\s*(?:…|\.\.\.)\s*")
_PART_SPLIT = re.compile(r"\s+[-–]\s+|\s*[·•,;/]\s*")
_NUM_PART = re.compile(r"^([-−]?\d+(?:[.,]\d+)?)\s*([^\d\s].{0,8})?$")
_SPELLED = r"\b{v}\s*\(\s*([A-Za-z][a-z]+)\s*\)"  # "C (Celsius)": the value's full name


_VALUES_LABEL = re.compile(r"^\s*(?:values?|settings?|options?|choices?)\s*:\s*", re.IGNORECASE)
_NAMED_STOP = re.compile(r"[A-Z]{2,6}|[A-Z][a-z]{1,5}")  # "AUTO", "Max": a word among numbers
_CHOICE = re.compile(r"[A-Za-z0-9][A-Za-z0-9+-]{0,9}(?: [A-Za-z0-9+-]{1,10})?")


DEFAULT_HEAD = re.compile(r"\b(?:factory|default|standard|preset|initial)\b", re.IGNORECASE)


@dataclass
class MenuItem:
    """One item of the menu: its code, the setting it names, and the units about it."""

    code: str
    name: str
    at: int
    texts: list[tuple[int, str]] = field(default_factory=list)  # (unit, text about its values)
    initial: str | None = None


def _parts(text: str) -> list[str] | None:
    """The values a printed run gives ("1 h - 2 h - 3 h - 4 h - 6 h", "-- (off) · 1 · 2 · 5 · 10
    min", "1 · 2 · 3 … 9"), numbers with their unit and "off", or None."""
    text = re.sub(r"\s*\((?:off|none)\)", "", text.strip().rstrip("."), flags=re.I)
    parts = [p.strip() for p in _PART_SPLIT.split(text) if p.strip()]
    if len(parts) < 3:
        return None
    out: list[str] = []
    unit = ""
    for p in parts:
        pieces = _ELLIPSIS.split(p)
        for k, piece in enumerate(pieces):
            if _OFF_MARK.match(piece):
                out.append("off")
                continue
            if _NAMED_STOP.fullmatch(piece):  # "OFF, AUTO, 5, 10 …": a named stop among numbers
                out.append(piece.lower())
                continue
            m = _NUM_PART.match(piece)
            if m is None or (
                m.group(2) and not unit_name(m.group(2).strip()) and m.group(2).strip()
            ):
                return None
            if k and len(out) >= 2:  # "3 … 9": the run's step fills the gap
                a, b2 = float(out[-2].split()[0]), float(out[-1].split()[0])
                step, hi = b2 - a, float(m.group(1).replace(",", "."))
                x = b2 + step
                while step > 0 and x < hi - 1e-9 and len(out) < 200:
                    out.append(f"{x:g}")
                    x += step
            out.append(m.group(1).replace(",", "."))
            if m.group(2):
                unit = m.group(2).strip()
    if sum(bool(re.match(r"[-−]?\d", v)) for v in out) < 2:
        return None
    return [v if v == "off" or not unit else f"{v} {unit}" for v in out]


def item_variable(b: Builder, item: MenuItem) -> str | None:
    """A variable for the item from what its own row or lines say (None: nothing usable)."""
    name = re.sub(r"\s*\(.*?\)", "", item.name).strip()
    ranges: list[Range] = []
    step: tuple[float, str] | None = None
    initial = next((f for _i, t in item.texts if (f := find_initial(t))), None)
    if (cases := _cases(b, item)) is not None:
        return cases
    for i, text in item.texts:
        if b.manual.units[i].cells and i != item.at:
            continue  # (a table under the item: its cases, read above)
        if ranges:  # (a range read first is the item's: no list after it, only its step)
            step = step or find_step(text)
            continue
        if (
            i == item.at
            and b.manual.units[i].cells
            and (cell := _cell_choices(b, item, name, text))
        ):
            return cell
        text = _VALUES_LABEL.sub("", text).split(". ")[0]  # "Values: OFF, 5, 10 minutes. …"
        run = re.search(r"(?<![\w.])(?:--|\d)", text)  # "The setback runs 0 h - 2 h - …"
        parts = _parts(text) or (_parts(text[run.start() :]) if run else None)
        if parts:
            return _listed(b, item, name, parts)
        found = find_list(text)
        listed = found[0] if found else bare_list(text) or []
        aside = re.search(r"\(([^()]*[/·,][^()]*)\)", text)  # "F1: temperature unit (C/F)"
        if not listed and aside and i == item.at:
            listed = [p.strip() for p in re.split(r"\s*[/·,]\s*", aside.group(1)) if p.strip()]
        if len(listed) >= 2 and (drawn := _drawn(b, item, name, listed)):
            return drawn
        if len(listed) >= 2 and not numeric_list(listed):
            values = []
            for v in listed:
                full = re.search(_SPELLED.format(v=re.escape(v)), text)
                values.append(full.group(1).lower() if full else v)
            return b.add_discrete(name, values, item.code, None)
        if not ranges:
            ranges = find_ranges(text)
        if step is None:
            step = find_step(text) or (bare_step(text) if i == item.at else None)
    if not ranges:
        return None
    r = ranges[0]
    if step and (not step[1] or unit_name(step[1]) == r.unit or not r.unit):
        r = Range(r.low, r.high, r.unit or step[1], r.step or step[0])
    ev = Evidence(ranges=[r], range_at=item.at, step=step, step_at=item.at)
    var = b.add_number(name, item.code, ev, cyclic=False)
    _as_printed(b, var, r.unit)
    if initial is not None:
        _start(b, var, initial[0], r.unit, item.at)
    elif item.initial and (num := re.match(r"[-−]?\d+(?:\.\d+)?", item.initial)):
        _start(b, var, float(num.group(0)), r.unit, item.at)
    return var


def _drawn(b: Builder, item: MenuItem, name: str, listed: list[str]) -> str | None:
    """Choices each printed as the symbol the display draws before its name ("▽ full face,
    △ nasal, ∘∘ pillows"): the user says the name, the display shows the symbol; the start
    is given by either."""
    found = [drawn_choice(v) for v in listed]
    if not all(found):
        return None
    pairs = [(m[0], m[1].lower()) for m in found if m]
    init = (item.initial or "").strip().lower()
    start = next((n for c, n in pairs if init and init in (c.lower(), n)), None)
    ev = Evidence(
        values=[n for _c, n in pairs], values_at=item.at, initial=start, initial_at=item.at
    )
    ev.shows = dict((n, c) for c, n in pairs)
    var = b.add_discrete(name, [n for _c, n in pairs], item.code, ev)
    return var


def _cell_choices(b: Builder, item: MenuItem, name: str, cell: str) -> str | None:
    """An item whose row cell prints coded choices ("0 = off, 1 = on": named values shown as
    their codes) or short words joined by slashes ("C / F"); its start from the row's default
    cell, matched to a code or a word."""
    coded = coded_choices(cell)
    pairs = coded or [(w, w) for w in slashed_words(cell) or _comma_words(cell) or []]
    if not pairs:
        return None
    init = (item.initial or "").strip().lower()
    start = next((n.lower() for c, n in pairs if init and init in (c.lower(), n.lower())), None)
    shows = {n.lower(): c for c, n in pairs} if coded else None
    ev = Evidence(
        values=[n for _c, n in pairs], values_at=item.at, initial=start, initial_at=item.at
    )
    ev.shows = shows
    var = b.add_discrete(name, [n for _c, n in pairs], item.code, ev)
    b.variables[var]["wrap"] = False
    return var


def _comma_words(cell: str) -> list[str] | None:
    """Short choices a row cell lists with commas, words among numbers ("ECO, 1, 2, 3") or two
    words ("ON, OFF"): the item's values as printed, not a range of its numbers nor nothing."""
    items = [i.strip() for i in cell.strip().rstrip(".").split(",")]
    if len(items) < 2 or not all(_CHOICE.fullmatch(i) for i in items):
        return None
    words = [i for i in items if re.search(r"[A-Za-z]{2}", i)]
    if not words or (len(items) > 2 and len(words) == len(items)):
        return None  # (three words or more: the list readers' job, as before)
    return items


def _as_printed(b: Builder, var: str, unit: str) -> None:
    """A duration the menu prints as a bare number ("P1 2.5" for 2.5 min) stays a number in
    its printed unit: read as a time it would be shown as 02:30, which the display never
    shows."""
    spec = b.variables[var]
    if spec["type"] != "time" or unit not in ("s", "min", "h"):
        return
    per = seconds(1, unit)
    spec["type"] = "numeric"
    spec["unit"] = unit
    spec.pop("format", None)
    spec["ranges"] = [
        [tidy_number(parse_hms(lo) / per), tidy_number(parse_hms(hi) / per), tidy_number(st / per)]
        for lo, hi, st in spec["ranges"]
    ]
    if "initial" in spec:
        spec["initial"] = tidy_number(parse_hms(spec["initial"]) / per)


def _start(b: Builder, var: str, value: float, unit: str, at: int) -> None:
    """Start ``var`` at ``value`` (in the unit its values were printed in) when it holds it."""
    spec = b.variables[var]
    if spec["type"] == "time":
        unit = unit if unit in ("s", "min", "h") else "min"
        start: Any = format_hms(seconds(value, unit))
        inside = any(
            parse_hms(lo) <= parse_hms(start) <= parse_hms(hi) for lo, hi, _ in spec["ranges"]
        )
    else:
        start = int(value) if float(value).is_integer() else value
        inside = any(lo <= value <= hi for lo, hi, _ in spec["ranges"])
    if inside:
        spec["initial"] = start
        b.note(f"variables.{var}.initial", f"starts at {start}", at)


_STEP_HEAD = re.compile(r"\b(?:step|one press|per press|increment)s?\b", re.IGNORECASE)


def _cases(b: Builder, item: MenuItem) -> str | None:
    """An item whose range depends on an earlier item, told as a table under it whose first
    column is headed by that item's code ("| unit (F1) | range | one press | default |", one
    row per unit): a setting with one case per value of the earlier item."""
    units = b.manual.units
    rows = [units[i] for i, _t in item.texts if units[i].cells and units[i].header and i != item.at]
    if not rows:
        return None
    head = rows[0].header
    parent = next(
        (
            v
            for v, spec in b.variables.items()
            if re.search(rf"\b{re.escape(str(spec.get('label')))}\b", head[0])
            and spec.get("type") == "discrete"
        ),
        None,
    )
    if parent is None:
        return None
    values = [str(v) for v in b.variables[parent]["values"]]
    cases: dict[str, Any] = {}
    for row in rows:
        key = row.cells[0].strip().lower()
        match = [v for v in values if v.lower() == key] or [
            v for v in values if v.lower().startswith(key)
        ]
        found = [r for c in row.cells[1:] for r in find_ranges(c)]
        if len(match) != 1 or not found:
            continue
        step, start = None, None
        for h, c in zip(head[1:], row.cells[1:], strict=False):
            num = re.fullmatch(r"\s*([-−]?\d+(?:\.\d+)?)\s*\S{0,3}\s*", c)
            if num and _STEP_HEAD.search(h):
                step = float(num.group(1))
            elif num and DEFAULT_HEAD.search(h):
                start = float(num.group(1))
        r = found[0]
        st = r.step or step or 1.0
        case: dict[str, Any] = {
            "ranges": [[tidy_number(r.low), tidy_number(r.high), tidy_number(st)]]
        }
        if start is not None and r.low <= start <= r.high:
            case["initial"] = tidy_number(start)
        cases[match[0]] = case
    if not cases:
        return None
    name = b.unique(re.sub(r"\s*\(.*?\)", "", item.name).strip(), b.variables)
    b.variables[name] = {
        "type": "numeric",
        "depends_on": parent,
        "cases": cases,
        "label": item.code,
    }
    b.note(f"variables.{name}.cases", f"its range per {parent}", b.manual.units.index(rows[0]))
    return name


def _listed(b: Builder, item: MenuItem, name: str, parts: list[str]) -> str:
    """An item whose values are printed one by one: numbers (a piecewise range) or, with "off"
    among them, a list of names."""
    initial = None
    if item.initial:
        init = item.initial.strip()
        initial = next(
            (
                p
                for p in parts
                if p.split()[0] == init.lower() or (p == "off" and _OFF_MARK.match(init))
            ),
            None,
        )
    if initial is None and (
        told := next((f for _i, t in item.texts if (f := find_initial(t))), None)
    ):
        initial = next((p for p in parts if p.split()[0] == f"{told[0]:g}"), None)
    if "off" not in parts and numeric_list(parts):
        var = b.add_number(name, item.code, list_evidence(Evidence(values=parts)), cyclic=False)
        unit = unit_name(parts[-1].split()[-1]) if " " in parts[-1] else ""
        _as_printed(b, var, unit)
        if initial is not None:
            _start(b, var, float(initial.split()[0]), unit, item.at)
        return var
    ev2 = Evidence(values=parts, values_at=item.at, initial=initial, initial_at=item.at)
    var = b.add_discrete(name, parts, item.code, ev2)
    b.variables[var]["wrap"] = False
    return var
