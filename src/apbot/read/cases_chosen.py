"""The amount a stepping pair sets, per value of the choice it works on.

Manuals often give one pair of keys a setting that belongs to whatever another key has chosen:
"▲ / ▼ — Raise / lower the heat level of the selected zone" under a ZONE key (each zone keeps
its own level), or a table of what the pair sets for each choice, the choice's values in one
column and a bare "Range" in another ("| Goal | Range | Step | Value when selected |" with rows
time / distance / calories). Either makes the pair's amount depend on that choice, a case per
value: the same range for each, kept per value, in the first; each row's range, step and
starting value in the second. Runs after the programme tables (``cases.py``), on amounts
they left alone.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import format_hms, parse_quantity
from apbot.read.build import Builder
from apbot.read.cases_tables import _parent_values, _tables
from apbot.read.goal_vocab import stem
from apbot.read.labels import words
from apbot.read.text import Unit
from apbot.read.values import find_ranges, seconds

_CHOSEN_RE = re.compile(
    r"\b(?:of|for)\s+the\s+(?:selected|chosen|current|active)\s+(?P<noun>[a-z]+)", re.I
)
# "12 - 18", "5 °C to 12 °C": the low end may carry the unit too
_SPAN_RE = re.compile(
    r"(\d+(?:\.\d+)?)\s*(?:°\s?[CF]\b|%|[a-zA-Z]{1,3}\b)?\s*(?:-|–|—|to)\s*(\d+(?:\.\d+)?)"
)
_NUMBER_RE = re.compile(r"\d+(?:\.\d+)?")
_RANGE_HEAD = {"range", "ranges", "setting", "settings", "adjustable", "available", "possible"}
_START_HEAD = {"default", "factory", "initial", "start", "starts", "selected", "preset"}


def chosen_cases(b: Builder) -> None:
    """Make each stepping pair's own amount depend on the choice its legend or a table names."""
    fixed = {v for g in b.guards for v in g["when"]}
    choices = {
        name: spec
        for name, spec in b.variables.items()
        if spec.get("type") == "discrete"
        and not spec.get("depends_on")
        and name not in fixed
        and len(spec.get("values", [])) >= 2
        and set(spec["values"]) != {"on", "off"}
        and _set_by_a_key(b, name)
    }
    for name, tokens in _paired_amounts(b):
        spec = b.variables[name]
        guessed = name in b.unread  # (a programme table may have given only the starts)
        if (spec.get("depends_on") and not guessed) or name in fixed:
            continue
        for parent, pspec in choices.items():
            if spec.get("depends_on") not in (None, parent):
                continue
            cases = _table_cases(b, name, parent, pspec["values"])
            if cases and spec.get("type") == "time" and not _timed(cases):
                cases = None  # a time takes only rows told as times
            # "of the selected zone": each keeps its own, whether a table gives the ranges or not
            remember = not spec.get("depends_on") and _said_of_the_chosen(b, tokens, parent, name)
            if cases is None and remember:
                cases = {v: {"ranges": spec["ranges"]} for v in pspec["values"]}
                if "initial" in spec:
                    for case in cases.values():
                        case["initial"] = spec["initial"]
            if not cases:
                continue
            for key in ("ranges", "initial", "values"):
                spec.pop(key, None)
            _as_time(spec, cases)
            spec["depends_on"] = parent
            spec["cases"] = cases
            if remember:
                spec["remember"] = True
            b.unread.discard(name)
            b.note(f"variables.{name}.cases", f"depends on {parent}: {len(cases)} cases")
            break


def _set_by_a_key(b: Builder, name: str) -> bool:
    return any(s.get("variable") == name for steps in b.features.values() for s in steps)


def _paired_amounts(b: Builder) -> list[tuple[str, list[str]]]:
    """Amounts a pair of keys steps both ways by itself (a feature of one step, next and
    prev), with the pair's controls."""
    out: list[tuple[str, list[str]]] = []
    for steps in b.features.values():
        if len(steps) != 1:
            continue
        effect = steps[0].get("effect")
        var = steps[0].get("variable")
        if (
            isinstance(effect, dict)
            and {"next", "prev"} <= {e for e in effect.values() if isinstance(e, str)}
            and var in b.variables
            and b.variables[var].get("type") in ("numeric", "time")
            and var not in {o[0] for o in out}
        ):
            tokens = [c for i in b.infos if i.name in effect for c in i.controls]
            out.append((var, sorted(set(tokens))))
    return out


def _said_of_the_chosen(b: Builder, tokens: list[str], parent: str, name: str) -> bool:
    """The pair's own sentence says it sets its amount "of the selected zone" (right after the
    amount's own noun: "do nothing in the current mode" is a condition, not whose amount it
    is), and the choice is the zone's."""
    own = set(words(name.replace("_", " ")))
    pwords = set(words(parent.replace("_", " "))) | set(
        words(str(b.variables[parent].get("label", "")))
    )
    for token in tokens:
        for i in b.labels[token].mentions if token in b.labels else []:
            label = b.labels[token].text.upper()
            for sentence in re.split(r"(?<=[.!?])\s+", b.manual.units[i].text):
                if label not in sentence.upper():
                    continue  # (the sentence naming the pair, in a legend of several keys)
                for m in _CHOSEN_RE.finditer(sentence):
                    said_of = words(sentence[: m.start()])[-3:]  # "the warmth OF the selected side"
                    if m.group("noun").lower() in pwords and own & set(said_of):
                        return True
    return False


def _table_cases(
    b: Builder, name: str, parent: str, values: list[str]
) -> dict[str, dict[str, Any]] | None:
    """A table with a column of the choice's values and a bare "Range" column, in a section
    that names the amount: each row's range, step and starting value."""
    own = {stem(w) for w in words(name.replace("_", " ")) if len(w) >= 4}  # HOLD: "Holding"
    for header, rows in _tables(b.manual.units):
        if len(rows) < 2 or not own & {stem(w) for w in words(rows[0].heading or "")}:
            continue
        hits = [
            sum(len(_parent_values(_cell(r, c), values)) == 1 for r in rows)
            for c in range(len(header))
        ]
        keyed = max(range(len(header)), key=lambda c: (hits[c], -c)) if header else None
        if keyed is not None and hits[keyed] < 2:
            keyed = None  # (the column naming the most values: "time" over the lamp's "TIME")
        span = next(
            (
                c
                for c in range(len(header))
                if words(header[c])
                and set(words(header[c])) <= _RANGE_HEAD
                and "range" in words(header[c])
            ),
            None,
        )
        if keyed is None or span is None:
            continue
        step = next((c for c in range(len(header)) if "step" in words(header[c])), None)
        start = next((c for c in range(len(header)) if set(words(header[c])) & _START_HEAD), None)
        cases: dict[str, dict[str, Any]] = {}
        times: dict[str, dict[str, Any]] = {}  # the same rows, when each is a time in words
        for row in rows:
            found = _parent_values(_cell(row, keyed), values)
            m = _SPAN_RE.search(_cell(row, span))
            if len(found) != 1 or m is None:
                continue
            timed = _time_case(row, span, step, start)
            if timed is not None:
                times[found[0]] = timed
            low, high = _num(m.group(1)), _num(m.group(2))
            by = _first_number(_cell(row, step)) if step is not None else None
            case: dict[str, Any] = {"ranges": [[low, high, by or 1]]}
            first = _first_number(_cell(row, start)) if start is not None else None
            if first is not None and low <= first <= high:
                case["initial"] = first
            cases[found[0]] = case
        if len(cases) >= 2:
            return times if times.keys() == cases.keys() else cases
    return None


def _time_case(row: Unit, span: int, step: int | None, start: int | None) -> dict[str, Any] | None:
    """A row whose range is a time in words ("15 – 45 minutes", "15 – 60 seconds"): its range,
    step and start in seconds (rows of one table may count in different units), or None."""
    found = find_ranges(_cell(row, span))
    if len(found) != 1 or found[0].unit not in ("s", "min", "h"):
        return None
    r = found[0]
    low, high = seconds(r.low, r.unit), seconds(r.high, r.unit)
    by = _quantity(_cell(row, step), r.unit) if step is not None else None
    case: dict[str, Any] = {"ranges": [[format_hms(low), format_hms(high), by or 60]]}
    first = _quantity(_cell(row, start), r.unit) if start is not None else None
    if first is not None and low <= first <= high:
        case["initial"] = format_hms(first)
    return case


def _quantity(cell: str, unit: str) -> int | None:
    """A cell's amount of time in seconds ("5 minutes"; a bare "5" in the range's unit)."""
    told = parse_quantity(cell.strip().lower())
    if told and told[1] == "time":
        return int(told[0])
    n = _first_number(cell)
    return seconds(n, unit) if n is not None else None


def _as_time(spec: dict[str, Any], cases: dict[str, dict[str, Any]]) -> None:
    """A setting whose cases were read as times: a time, shown as minutes:seconds when a step
    is under a minute."""
    if _timed(cases):
        spec["type"] = "time"
        spec.pop("unit", None)
        steps = [c["ranges"][0][2] for c in cases.values()]
        spec["format"] = "mm:ss" if min(steps) < 60 else "h:mm"


def _timed(cases: dict[str, dict[str, Any]]) -> bool:
    return all(isinstance(c["ranges"][0][0], str) for c in cases.values())


def _cell(row: Unit, column: int) -> str:
    return row.cells[column] if column < len(row.cells) else ""


def _first_number(text: str) -> float | int | None:
    m = _NUMBER_RE.search(text)
    return _num(m.group(0)) if m else None


def _num(text: str) -> float | int:
    value = float(text)
    return int(value) if value.is_integer() else value
