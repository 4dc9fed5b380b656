"""Programme-dependent settings from tables: one row per programme, one column per setting.

Manuals give what a setting allows in each programme as a table ("| Program | Temperature |
Spin |", "| Menu | Texture options |"). A table whose first column names values of an already
read programme variable, and whose other column names another variable, turns that variable
into a dependent one with a case per row; a row that says nothing usable ("—", "fixed",
"automatic") leaves the setting out of that programme, as the manual implies.
"""

from __future__ import annotations

import itertools
import math
import re
from typing import Any

from apbot.model.values import format_hms, parse_hms
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.shapes import CHOICE_WORDS
from apbot.read.text import Unit
from apbot.read.values import find_ranges, number, unit_name

GENERIC = {
    "options", "option", "range", "ranges", "setting", "settings", "available", "values",
    "suggested", "default", "standard", "possible", "adjustable", "choices", "max", "min",
}  # fmt: skip
DEFAULT_WORDS = {"default", "standard", "preset", "initial", "factory"}
ADVICE_WORDS = {"suggested", "recommended", "typical", "advised", "usual"}  # not limits


def _tables(units: list[Unit]) -> list[tuple[tuple[str, ...], list[Unit]]]:
    out: list[tuple[tuple[str, ...], list[Unit]]] = []
    previous: Unit | None = None
    for unit in units:
        if unit.cells and unit.header:
            last = out[-1][1][-1] if out and out[-1][0] == unit.header else None
            if last is not None and (last.line >= unit.line - 1 or last is previous):
                out[-1][1].append(unit)  # the next row, also after rows wrapped onto two lines
            else:
                out.append((unit.header, [unit]))
        previous = unit
    return out


def _norm(text: str) -> str:
    return re.sub(r"\s+", " ", re.sub(r"[*_`]", "", text).strip().lower()).strip(" .")


def _parent_values(cell: str, values: list[str]) -> list[str]:
    """Which of the parent's values a first cell names ("White, Quick Cook" → two)."""
    found = []
    for part in re.split(r"\s*(?:,|/|&|\band\b)\s*", _norm(cell)):
        part = re.sub(r"^\d+[.)]?\s*", "", part)
        if part in values:  # "White" is WHITE even where WHITE QUICK comes first
            found.append(part)
            continue
        for value in values:
            if part and len(part) >= 4 and value.startswith(part):
                found.append(value)
                break
    exact = _norm(cell)
    if exact in values and exact not in found:
        found = [exact]
    return found


def _matches(header: str, name: str, spec: dict[str, Any]) -> bool:
    hw = [w for w in words(header) if w not in GENERIC]
    if not hw:
        return False
    vw = set(words(name.replace("_", " "))) | set(words(str(spec.get("label", ""))))
    if any(
        h == v or (min(len(h), len(v)) >= 4 and (h.startswith(v) or v.startswith(h)))
        for h in hw
        for v in vw
    ):
        return True
    unit = spec.get("unit", "")
    return bool(unit) and unit.lower() in header.lower().replace(" ", "")


def apply_cases(b: Builder) -> None:
    """Turn read variables into programme-dependent ones where a table says so."""
    fixed = {v for g in b.guards for v in g["when"]}  # power, lock, running: never per programme
    parents: set[str] = set()
    children: set[str] = set()
    keys = {lab.text.strip(" .").upper() for lab in b.labels.values() if lab.text}
    for header, rows in _tables(b.manual.units):
        if len(rows) < 2:
            continue
        if sum(h.strip(" *.").upper() in keys for h in header) >= 2:
            continue  # a column per key ("| TEMP. | SPIN | SOIL |"): each lists its own values
        parent, best = None, (1, False)
        for name, spec in b.variables.items():
            if spec.get("type") != "discrete" or spec.get("depends_on") or len(spec["values"]) < 3:
                continue
            if name in fixed or name in children:
                continue
            hits = sum(bool(_parent_values(r.cells[0], spec["values"])) for r in rows)
            score = (hits, bool(set(words(name.replace("_", " "))) & CHOICE_WORDS))
            if hits >= 2 and score > best:
                parent, best = name, score
        if parent is None:
            continue
        pvalues = b.variables[parent]["values"]
        header = _named_ranges(header, rows)
        for column in range(1, len(header)):
            if set(words(header[column])) & (DEFAULT_WORDS | ADVICE_WORDS):
                continue
            if _STEP_HEAD_RE.search(header[column]):
                continue  # "Time step": each row's step (read by _row_steps), not its values
            head = [w for w in words(header[column]) if w not in GENERIC][:1]
            named = sorted(  # "Wash (min)": the variable named wash before any other "min" one
                b.variables.items(), key=lambda item: not set(head) & set(words(item[0]))
            )
            for name, spec in named:
                if name == parent or name in fixed | parents or spec.get("depends_on"):
                    continue
                if not _matches(header[column], name, spec):
                    continue
                if spec.get("type") == "discrete" and _ranges_column(rows, column):
                    _as_number(b, name, spec, rows, column)  # the table says it is an amount
                cases = _cases(spec, rows, column, pvalues)
                if len(cases) >= 2 and _presets(b, parent, name, cases, rows[0]):
                    break
                if len(cases) >= 2:
                    if all("initial" in c for c in cases.values()) and spec.get("values"):
                        for value in pvalues:  # defaults per programme: the others keep all
                            cases.setdefault(value, {"values": list(spec["values"])})
                    _row_steps(spec, cases, header, rows, column, pvalues)
                    _defaults(spec, cases, header, rows, column, pvalues)
                    for key in ("values", "ranges", "initial"):
                        spec.pop(key, None)
                    spec["depends_on"] = parent
                    spec["cases"] = cases
                    _header_unit(spec, header[column])
                    parents.add(parent)
                    children.add(name)
                    _no_toggle(b, name, cases)
                    b.note(
                        f"variables.{name}.cases",
                        f"depends on {parent}: {len(cases)} cases",
                        b.manual.units.index(rows[0]),
                    )
                break


_YES_NO = {"yes", "no", "y", "n", "—", "-", "–", ""}


def _named_ranges(header: tuple[str, ...], rows: list[Unit]) -> tuple[str, ...]:
    """ "| Cook time adjustable? | Range |": the column that only says yes or no names the
    setting, the bare "Range" column next to it holds its values (a "no" row's range is "—")."""
    out = list(header)
    for c in range(1, len(header)):
        cells = [r.cells[c].strip(" *").lower() if c < len(r.cells) else "" for r in rows]
        if not all(cell in _YES_NO for cell in cells) or "yes" not in cells:
            continue
        for r in range(c + 1, min(c + 3, len(header))):
            if re.fullmatch(r"\W*(?:setting |adjustment |time )?range\W*", header[r], re.I):
                name = re.sub(r"\b(?:adjustable|settable|available|can be set)\b|\?", "", header[c])
                out[r], out[c] = name.strip(), "adjustable"
                break
    return tuple(out)


def _presets(b: Builder, parent: str, name: str, cases: dict[str, Any], row: Unit) -> bool:
    """Keys that each load one amount ("FRIES — 200 °C", "BOIL — 100 °C") give the amount a
    starting value per preset, not a one-value domain: the +/− keys still adjust it over its
    whole range (a preset the table leaves out keeps the range, from its start). Only for a
    table of single values."""
    spec = b.variables[name]
    if spec.get("type") not in ("numeric", "time") or not spec.get("ranges"):
        return False
    if not set(cases) <= set(b.variables[parent].get("values", [])):
        return False
    single: dict[str, Any] = {}
    for value, case in cases.items():
        ranges = case.get("ranges") or []
        if len(ranges) != 1 or ranges[0][0] != ranges[0][1]:
            return False
        single[value] = ranges[0][0]
    ranges = [list(r) for r in spec["ranges"]]
    if spec["type"] == "numeric":
        lo, hi, step = ranges[0][0], ranges[-1][1], ranges[0][2]
        values = list(single.values())
        if (
            len(ranges) > 1
            or any((v - lo) % step for v in values)
            or min(values) < lo
            or max(values) > hi
        ):
            low, high = min([lo, *values]), max([hi, *values])
            step = _gcd_step(step, single, low)
            ranges = [[low, low + int((high - low) / step) * step, step]]
    else:
        secs = [parse_hms(str(v)) for v in single.values()]
        lo_t, hi_t = parse_hms(ranges[0][0]), parse_hms(ranges[-1][1])
        if (
            min(secs) < lo_t
            or max(secs) > hi_t
            or any((t - lo_t) % int(ranges[0][2]) for t in secs)
        ):
            return False
    for key in ("ranges", "initial", "values"):
        spec.pop(key, None)
    spec["depends_on"] = parent
    spec["cases"] = {
        v: {"ranges": ranges, **({"initial": single[v]} if v in single else {})}
        for v in b.variables[parent]["values"]
    }
    b.note(
        f"variables.{name}.cases",
        f"each {parent} loads its own starting value: "
        + ", ".join(f"{k} {v}" for k, v in single.items()),
        b.manual.units.index(row),
    )
    return True


def _gcd_step(step: float, values: dict[str, Any], low: float) -> float:
    """The largest step from ``low`` that reaches every preset (1 when they are whole)."""
    from math import gcd

    if all(float(v).is_integer() for v in values.values()) and float(step).is_integer():
        g = int(step)
        for v in values.values():
            g = gcd(g, int(v - low))
        return g or 1
    return 1 if all(float(v).is_integer() for v in values.values()) else 0.5


HEADER_UNIT_RE = re.compile(  # "(s)" glued to a word is a plural ending ("Option(s)")
    r"\(\s*(min|mins|minutes|h|hrs|hours|sec|°c|°f|%|rpm|w|g|kg|ml|l)\s*\)"
    r"|(?<![A-Za-z])\(\s*(s)\s*\)",
    re.I,
)


def _header_unit(spec: dict[str, Any], header: str) -> None:
    """A column headed with its unit ("Wash (min)", "Temp (°C)") gives an amount read without
    one that unit, so that a goal's "24-minute wash" finds it."""
    if spec.get("type") != "numeric" or spec.get("unit"):
        return
    m = HEADER_UNIT_RE.search(header)
    if m:
        spec["unit"] = unit_name(m.group(1) or m.group(2))


def _ranges_column(rows: list[Unit], column: int) -> bool:
    return sum(bool(column < len(r.cells) and find_ranges(r.cells[column])) for r in rows) >= 2


def _as_number(b: Builder, name: str, spec: dict[str, Any], rows: list[Unit], column: int) -> None:
    """Turn a read-as-discrete setting into the amount the table's ranges say it is."""
    from apbot.read.shapes import Evidence

    found = [find_ranges(r.cells[column]) for r in rows if column < len(r.cells)]
    first = next(f[0] for f in found if f)
    label = spec.get("label", name.upper())
    del b.variables[name]
    new = b.add_number(name, label, Evidence(ranges=[first]), cyclic=False)
    if new != name:  # keep the name the features use
        b.variables[name] = b.variables.pop(new)
    spec.clear()
    spec.update(b.variables[name])
    b.variables[name] = spec
    _no_toggle(b, name, {"x": {"values": []}})


def _no_toggle(b: Builder, name: str, cases: dict[str, Any]) -> None:
    """A toggle on a setting that now has more than two values in some programme steps on."""
    if all(len(c.get("values", [])) == 2 for c in cases.values()):
        return
    for steps in b.features.values():
        for step in steps:
            if step.get("variable") != name:
                continue
            effect = step.get("effect")
            if effect == "toggle":
                step["effect"] = "next"
            elif isinstance(effect, dict):
                step["effect"] = {a: "next" if e == "toggle" else e for a, e in effect.items()}


def _cases(
    spec: dict[str, Any], rows: list[Unit], column: int, pvalues: list[str]
) -> dict[str, Any]:
    cases: dict[str, Any] = {}
    for row in rows:
        if column >= len(row.cells):
            continue
        cell = row.cells[column]
        targets = _parent_values(row.cells[0], pvalues)
        if not targets:
            continue
        case = _case(spec, cell)
        if case is None:
            continue
        for target in targets:
            cases.setdefault(target, case)
    return cases


def _value_span(values: list[str], cell: str) -> list[str] | None:
    """The listed values from one to another ("COLD – 60 °C" over cold, 20, 30, 40, 60, 90)."""
    m = re.fullmatch(r"\s*(.+?)\s*(?:–|—|-|\bto\b)\s*(.+?)\s*", cell)
    if not m or len(values) < 3:
        return None
    unit = r"\s*(?:°\s*[cf]|°|rpm|%)?\s*"
    ends = [re.sub(rf"^{unit}|{unit}$", "", _norm(x)) for x in m.groups()]
    if not all(e in values for e in ends):
        return None
    a, b = values.index(ends[0]), values.index(ends[1])
    return values[a : b + 1] if a < b else None


def _case(spec: dict[str, Any], cell: str) -> Any:
    kind = spec.get("type")
    if kind == "discrete":
        if len(spec.get("values", [])) == 2 and _norm(cell) in spec["values"]:
            return {"values": list(spec["values"]), "initial": _norm(cell)}  # a default
        span = _value_span(spec.get("values", []), cell)
        if span:
            return {"values": span}  # "cold – 60 °C" over the knob's marks
        known = spec.get("values", [])
        spaced = _norm(re.sub(r"\(.*?\)", "", cell)).split()
        if len(spaced) >= 2 and all(w in known for w in spaced):
            return {"values": spaced}  # "SOFT MEDIUM FIRM": the values, printed with spaces
        items = [
            _norm(re.sub(r"\(.*?\)", "", i)) for i in re.split(r"\s*(?:,|/|·|\bor\b)\s*", cell)
        ]
        items = [i for i in items if i and i not in ("—", "-", "–", "n/a") and len(i) <= 24]
        return {"values": list(dict.fromkeys(items))} if items else None
    ranges = spec.get("ranges") or []
    if not ranges:
        return None
    ranges_read = find_ranges(cell)
    if kind == "time":
        listed = None if ranges_read else _time_list(cell)
        if listed:  # "30, 45 or 60 minutes": the times, by the step between them
            gap = math.gcd(*[b - a for a, b in itertools.pairwise(listed)])
            return {"ranges": [[format_hms(listed[0]), format_hms(listed[-1]), gap]]}
        if not ranges_read:
            from apbot.model.values import parse_quantity

            q = parse_quantity(cell.strip().lower())
            if not q or q[1] != "time" or q[0] <= 0:
                return None
            return {"ranges": [[format_hms(int(q[0])), format_hms(int(q[0])), int(ranges[0][2])]]}
        r = ranges_read[0]
        factor = 1 if r.unit == "s" else {"min": 60, "h": 3600}.get(r.unit or "min", 60)
        t_lo, t_hi = int(r.low * factor), int(r.high * factor)
        t_step = min(int(ranges[0][2]), max(1, t_hi - t_lo))
        if (t_hi - t_lo) % t_step:  # "20 to 60 minutes" by 15: the step that reaches both ends
            t_step = math.gcd(t_step, t_hi - t_lo)
        t_hi = t_lo + (t_hi - t_lo) // t_step * t_step
        return {"ranges": [[format_hms(t_lo), format_hms(t_hi), t_step]]}
    step = float(ranges[0][2])
    if ranges_read:
        lo, hi = ranges_read[0].low, ranges_read[0].high
    else:
        m = re.fullmatch(r"\s*(\d+(?:[.,]\d+)?)\s*(\S*)\s*", cell)
        if not m or (m.group(2) and unit_name(m.group(2)) not in ("", spec.get("unit", ""))):
            return None
        value = number(m.group(1))
        if value is None:
            return None
        lo = hi = value
    count = int((hi - lo) / step + 1e-9)
    hi = lo + count * step
    tidy = lambda x: int(x) if float(x).is_integer() else round(x, 4)  # noqa: E731
    return {"ranges": [[tidy(lo), tidy(hi), tidy(step)]]}


_TIME_LIST_RE = re.compile(
    r"\s*(\d+(?:\s*(?:,|\bor\b|\band\b|/)\s*\d+)+)\s*(min(?:ute)?s?|h(?:ou)?rs?|hours?|h)\.?\s*",
    re.IGNORECASE,
)


def _time_list(cell: str) -> list[int] | None:
    """Three or more times in a cell ("30, 45 or 60 minutes"), rising, in seconds; else None."""
    m = _TIME_LIST_RE.fullmatch(cell)
    if not m:
        return None
    per = 3600 if unit_name(m.group(2)) == "h" else 60
    found = [int(x) * per for x in re.findall(r"\d+", m.group(1))]
    rising = all(a < b for a, b in itertools.pairwise(found))
    return found if len(found) >= 3 and rising else None


def _defaults(
    spec: dict[str, Any],
    cases: dict[str, Any],
    header: tuple[str, ...],
    rows: list[Unit],
    column: int,
    pvalues: list[str],
) -> None:
    """A "default"/"standard" column next to the setting's column gives each case's initial."""
    for c in range(1, len(header)):
        if c == column or not set(words(header[c])) & DEFAULT_WORDS:
            continue
        for row in rows:
            if c >= len(row.cells):
                continue
            for target in _parent_values(row.cells[0], pvalues):
                case = cases.get(target)
                if case is None:
                    continue
                cell = _norm(row.cells[c])
                if spec.get("type") == "discrete" and cell in case.get("values", []):
                    case["initial"] = cell
                elif spec.get("type") == "time" and case.get("ranges"):
                    start = _duration(cell)  # "| Preset time | 1:30 |"
                    if start is not None and _within(case["ranges"], start):
                        case["initial"] = format_hms(start)
        break


_STEP_HEAD_RE = re.compile(
    r"\b(?:each|every|per)\b.*\b(?:press|touch|tap|click|step)\b|\bsteps?\b", re.I
)


def _row_steps(
    spec: dict[str, Any],
    cases: dict[str, Any],
    header: tuple[str, ...],
    rows: list[Unit],
    column: int,
    pvalues: list[str],
) -> None:
    """A column headed "Each + / – press" (or "Step") next to a time's ranges gives each row's
    step ("| 0:45 – 2:00 | 15 min |")."""
    if spec.get("type") != "time":
        return
    for c in range(1, len(header)):
        if c == column or not _STEP_HEAD_RE.search(header[c]):
            continue
        for row in rows:
            step = _duration(_norm(row.cells[c])) if c < len(row.cells) else None
            if not step:
                continue
            for target in _parent_values(row.cells[0], pvalues):
                case = cases.get(target)
                if not case or not case.get("ranges") or len(case["ranges"]) != 1:
                    continue
                lo, hi, _ = case["ranges"][0]
                a, b = _seconds(lo), _seconds(hi)
                if b > a and (b - a) % step == 0:
                    case["ranges"] = [[lo, hi, step]]
        break


def _duration(cell: str) -> int | None:
    """Seconds in "15 min", "1:30" (h:mm), "20 s"; None for anything else."""
    from apbot.model.values import parse_quantity

    m = re.fullmatch(r"\s*(\d{1,2}):([0-5]\d)\s*", cell)
    if m:
        return int(m.group(1)) * 3600 + int(m.group(2)) * 60
    q = parse_quantity(cell.strip().lower())
    return int(q[0]) if q and q[1] == "time" and q[0] > 0 else None


def _seconds(hms: str) -> int:
    h, m, sec = (int(x) for x in str(hms).split(":"))
    return h * 3600 + m * 60 + sec


def _within(ranges: list[list[Any]], value: int) -> bool:
    return any(
        _seconds(lo) <= value <= _seconds(hi) and (value - _seconds(lo)) % int(st) == 0
        for lo, hi, st in ranges
    )


STAY_RE = re.compile(
    r"\b(?:stays?|remains?|kept|keeps?|unchanged|not (?:reset|lost|changed?|cleared))\b", re.I
)
RESET_NOUN_RE = re.compile(
    r"\b(?:programmes?|programs?|menus?|modes?|presets?|functions?|cycles?|courses?)\b", re.I
)
RESET_RE = re.compile(
    r"\b(?:programmes?|programs?|menus?|modes?|presets?|functions?|cycles?|courses?|selector)\b"
    r"[^.]*\b(?:defaults?|standard values|reset|go(?:es)? back|return|wipes?|clear|lost|forget)"
    r"|\b(?:defaults?|reset|go(?:es)? back|return|wipes?|clear|lost)\b[^.]*"
    r"\b(?:programmes?|programs?|menus?|modes?|presets?|functions?|cycles?|courses?)\b",
    re.IGNORECASE,
)


def apply_resets(b: Builder) -> None:
    """ "Choosing a programme loads its defaults": the programme's steps reset the settings."""
    units = b.manual.units
    at = next(
        (i for i, u in enumerate(units) if RESET_RE.search(u.text) and not STAY_RE.search(u.text)),
        None,
    )
    if at is None:
        return
    kept = {  # "your taste choice stays the same when you change the mode"
        n
        for u in units
        if STAY_RE.search(u.text) and RESET_NOUN_RE.search(u.text)
        for n in b.variables
        if set(words(n.replace("_", " "))) & set(words(u.text))
    }
    fixed = {v for g in b.guards for v in g["when"]}
    parents = {s.get("depends_on") for s in b.variables.values()} - {None}
    choices = [
        n
        for n, s in b.variables.items()
        if s.get("type") == "discrete"
        and n not in fixed
        and (n in parents or set(words(n.replace("_", " "))) & CHOICE_WORDS)
    ]
    if not choices:
        return
    choice = choices[0]
    others = [
        n
        for n, s in b.variables.items()
        if n != choice
        and n not in fixed
        and n not in kept
        and s.get("depends_on") is None
        and n != "running"
    ]
    if not others:
        return
    for steps in b.features.values():
        for step in steps:
            if step.get("variable") == choice:
                step["reset"] = [n for n in others if n != step.get("variable")]
    b.note(f"variables.{choice}", f"choosing it resets {', '.join(others)}", at)
