"""One programme table column's cells → values per programme, defaults and step durations.

Split out of ``cases.py`` (which decides which table and column make a dependent setting):
turning a cell ("30-90 min", "Yes", "40, 60 °C", "—") into a case value is a job of its own.
"""

from __future__ import annotations

import itertools
import math
import re
from typing import Any

from apbot.model.values import format_hms
from apbot.read.cases_tables import _norm, _parent_values
from apbot.read.labels import words
from apbot.read.text import Unit
from apbot.read.values import find_ranges, number, unit_name

DEFAULT_WORDS = {"default", "standard", "preset", "initial", "factory"}


_BRACKETED = re.compile(r"\[[^\]]*\]|\([^)]*\)")


def defaults_head(head: str, cells: list[str]) -> bool:
    """A column of defaults ("Default", "Standard time", "max (preset)" over "1400 (1200)"),
    not a column of a setting's values whose default is marked in its cells and named in
    brackets in its head ("Temperatures [default]" over "20 30 [40] 60", "Cooking time
    [standard]" over "0:20 – 1:30 [0:40]"): there the cells, the marked part aside, list
    several values or a range."""
    if not set(words(head)) & DEFAULT_WORDS:
        return False
    if set(words(_BRACKETED.sub(" ", head))) & DEFAULT_WORDS:
        return True
    filled = [c for c in cells if re.search(r"[^\W_]", c)]
    several = sum(
        bool(find_ranges(c)) or len(re.split(r"\s*,\s*|\s+", _BRACKETED.sub(" ", c).strip())) >= 2
        for c in filled
    )
    return several * 2 <= len(filled)


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


def _stepped(cell: str) -> list[str]:
    """The values of a cell that steps through them with arrows, each once: the one the last
    arrow comes round to ("→ 1 …" after "1 COARSE") is the first again."""
    items = [_norm(i).strip(" -–—…") for i in re.split(r"\s*→\s*", cell)]
    items = [i for i in items if i]
    if len(items) >= 3 and (items[-1] == items[0] or items[0].startswith(items[-1] + " ")):
        items.pop()
    return items


# a fraction of a measure ("1/4", "3/8 cup"): its slash joins, it does not part two items
_FRACTION = re.compile(r"(?<![\d/.])([1-9])/([2-9]|1[0-6])(?![\d/])")


def _cell_items(cell: str) -> list[str]:
    """A chart cell's items ("LOW / HIGH", "1/4, 1/2, 3/4 cup"): parted at commas, slashes
    and "or", a fraction kept whole where fractions are meant (two or more, or one before its
    measure: "1/2 cup"; a lone "1/2" is levels 1 or 2); a unit said once after the last amount
    is each one's."""
    fractions = _FRACTION.findall(cell)
    measured = re.search(_FRACTION.pattern + r"\s+(?!or\b|and\b|to\b)[a-z]", cell, re.I)
    # one "1/2" alone is levels 1 or 2; fractions are two or more, or one of a measure
    kept = _FRACTION.sub("\\1\u2044\\2", cell) if len(fractions) >= 2 or measured else cell
    items = [i.replace("\u2044", "/") for i in re.split(r"\s*(?:,|/|·|\bor\b)\s*", kept)]
    if kept == cell:
        return items
    tail = re.fullmatch(r"(\d+/\d+)\s+([a-z]{1,5})\.?", items[-1].strip(), re.I)
    if tail and all(_FRACTION.fullmatch(i.strip()) or i.strip().isdigit() for i in items[:-1]):
        items[-1] = tail.group(1)  # "1/4, 1/2, 3/4 cup": the measure's parts, its noun aside
    return items


def _spelled_out(item: str, known: list[str]) -> str:
    """A value a chart cell shortens ("med" for medium): the one known value it begins."""
    if item in known or len(item) < 3:
        return item
    longer = [k for k in known if isinstance(k, str) and k.startswith(item)]
    return longer[0] if len(longer) == 1 else item


def _alone(item: str, known: list[str]) -> str:
    """ "OFF only", "only ECO": the one value a row allows, said with "only" around it."""
    bare = re.sub(r"^only\s+|\s+only$", "", item)
    return bare if bare != item and (bare in known or not known) else item


# a mark that a chart's on/off column says the option is offered, or not ("–", "no",
# "not used"); a cross ("x", "✗") is "not possible" in as many charts as it is "offered" in
# others: neither
_OFFERED_RE = re.compile(r"\s*(?:(?:yes|y)\b|[✓✔●])\W*(?:\s|$)", re.I)
_NOT_OFFERED_RE = re.compile(r"\s*(?:no\b|not\b|n\b|[–—-](?:\s|$))", re.I)


def _toggle_cell(cell: str) -> bool | None:
    """Whether an on/off option's chart cell says it is offered (True), not offered (False),
    or neither (None: the cell names values). A note run into the cell from the next column
    ("– hold not possible") does not change what its first mark says."""
    if _OFFERED_RE.match(cell + " "):
        return True
    if _NOT_OFFERED_RE.match(cell + " ") or not cell.strip():
        return False
    return None


def _case(spec: dict[str, Any], cell: str) -> Any:
    kind = spec.get("type")
    if kind == "discrete" and sorted(spec.get("values", [])) == ["off", "on"]:
        said = _toggle_cell(cell)  # "yes" under STEAM: the key works in that programme
        if said is not None:
            return {"values": ["off", "on"]} if said else None
    if kind == "discrete":
        if len(cell.strip()) == 1 and not cell.strip().isalnum():
            return None  # "●" / "–": offered or not, no values (cases_marks reads such charts)
        if len(spec.get("values", [])) == 2 and _norm(cell) in spec["values"]:
            return {"values": list(spec["values"]), "initial": _norm(cell)}  # a default
        span = _value_span(spec.get("values", []), cell)
        if span:
            return {"values": span}  # "cold – 60 °C" over the knob's marks
        known = spec.get("values", [])
        spaced = _norm(re.sub(r"\(.*?\)", "", cell)).split()
        marked = [w[1:-1] for w in spaced if re.fullmatch(r"\[[^\]]+\]", w)]
        spaced = [w.strip("[]") for w in spaced]
        if len(spaced) >= 2 and all(w in known for w in spaced):
            # "SOFT MEDIUM FIRM": the values, printed with spaces ("[40]": the default)
            return {"values": spaced} | ({"initial": marked[0]} if len(marked) == 1 else {})
        items = [_norm(re.sub(r"\(.*?\)", "", i)) for i in _cell_items(cell)]
        if "→" in cell:  # "30 → 60 → 90 → 120", "1 COARSE → 2 FINE → 1 …": the key's order
            items = _stepped(cell)
        items = [_spelled_out(_alone(i, known), known) for i in items]
        items = [i for i in items if i and i not in ("—", "-", "–", "n/a") and len(i) <= 24]
        return {"values": list(dict.fromkeys(items))} if items else None
    ranges = spec.get("ranges") or []
    if not ranges:
        return None
    chained = chain_values(cell)
    if chained is not None:  # "0-1-3-[5]-7-9": the values one by one, the default in brackets
        return _chain_case(spec, *chained)
    ranges_read = find_ranges(cell)
    if kind == "time":
        times = None if ranges_read else time_list(cell)
        if times:  # "30, 45 or 60 minutes": the times, by the step between them
            listed, standard = times
            gap = math.gcd(*[b - a for a, b in itertools.pairwise(listed)])
            case = {"ranges": [[format_hms(listed[0]), format_hms(listed[-1]), gap]]}
            return case | ({"initial": format_hms(standard)} if standard is not None else {})
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


# three or more numbers joined by single hyphens, one of them maybe in brackets: the values a
# key steps through ("6-9-[12]-15-18"), not a range
_CHAIN_RE = re.compile(r"\s*\[?\d+(?:\.\d+)?\]?(?:\s*-\s*\[?\d+(?:\.\d+)?\]?){2,}\s*")


# two numbers so joined, one in brackets ("[1]-2", "2-[3]"): two values, not a range
_PAIR_RE = re.compile(r"\s*(?:\[\d+\]\s*-\s*\d+|\d+\s*-\s*\[\d+\])\s*")


def chain_values(cell: str) -> tuple[list[float], float | None] | None:
    """The rising numbers of a hyphen-chained cell and the bracketed default; else None."""
    if not _CHAIN_RE.fullmatch(cell) and not _PAIR_RE.fullmatch(cell):
        return None
    items = [x.strip() for x in cell.split("-")]
    numbers = [float(x.strip("[] ")) for x in items]
    if any(b <= a for a, b in itertools.pairwise(numbers)):
        return None
    default = next((float(x.strip("[] ")) for x in items if x.startswith("[")), None)
    return numbers, default


def _chain_case(spec: dict[str, Any], numbers: list[float], default: float | None) -> Any:
    """A case of listed numbers: one range per run of equal gaps (0-1-3-5: 0–1 by 1, 1–5 by
    2), in seconds of the unit the setting was read in when it is a time (minutes if none)."""
    scale = 1.0
    if spec.get("type") == "time":
        scale = {"s": 1, "h": 3600}.get(spec.get("unit", ""), 60)
    values = [v * scale for v in numbers]
    pieces: list[list[float]] = []
    for a, b in itertools.pairwise(values):
        if pieces and math.isclose(pieces[-1][2], b - a) and pieces[-1][1] == a:
            pieces[-1][1] = b
        else:
            pieces.append([a, b, b - a])
    tidy = lambda x: int(x) if float(x).is_integer() else round(x, 4)  # noqa: E731
    case: dict[str, Any] = {}
    if spec.get("type") == "time":
        case["ranges"] = [
            [format_hms(int(lo)), format_hms(int(hi)), int(st)] for lo, hi, st in pieces
        ]
        if default is not None:
            case["initial"] = format_hms(int(default * scale))
    else:
        case["ranges"] = [[tidy(lo), tidy(hi), tidy(st)] for lo, hi, st in pieces]
        if default is not None:
            case["initial"] = tidy(default)
    return case


# (one of them may be in brackets, the standard one: "20 / 30 / [40] / 50 / 60 min")
_TIME_LIST_RE = re.compile(
    r"\s*(\[?\d+\]?(?:\s*(?:,|\bor\b|\band\b|/)\s*\[?\d+\]?)+)\s*"
    r"(min(?:ute)?s?|h(?:ou)?rs?|hours?|h)\.?\s*",
    re.IGNORECASE,
)


def _time_list(cell: str) -> list[int] | None:
    """Three or more times in a cell ("30, 45 or 60 minutes"), rising, in seconds; else None."""
    listed = time_list(cell)
    return listed[0] if listed else None


def time_list(cell: str) -> tuple[list[int], int | None] | None:
    """Three or more rising times in a cell ("30, 45 or 60 minutes", "[30] / 45 / 60 min") in
    seconds, and the one in brackets (the standard time) if any; else None."""
    m = _TIME_LIST_RE.fullmatch(cell)
    if not m or m.group(1).count("[") > 1:
        return None
    per = 3600 if unit_name(m.group(2)) == "h" else 60
    found = [int(x) * per for x in re.findall(r"\d+", m.group(1))]
    rising = all(a < b for a, b in itertools.pairwise(found))
    marked = re.search(r"\[(\d+)\]", m.group(1))
    default = int(marked.group(1)) * per if marked else None
    return (found, default) if len(found) >= 3 and rising else None


def _cell(row: Unit, column: int) -> str:
    return row.cells[column] if column < len(row.cells) else ""


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
        if c == column or not defaults_head(header[c], [_cell(r, c) for r in rows]):
            continue
        for row in rows:
            if c >= len(row.cells):
                continue
            for target in _parent_values(row.cells[0], pvalues):
                case = cases.get(target)
                if case is None:
                    continue
                cell = _spelled_out(_norm(row.cells[c]), case.get("values", []))
                if spec.get("type") == "discrete" and cell in case.get("values", []):
                    case["initial"] = cell
                elif spec.get("type") == "time" and case.get("ranges"):
                    start = _duration(cell)  # "| Preset time | 1:30 |"
                    if start is not None and _within(case["ranges"], start):
                        case["initial"] = format_hms(start)
                elif spec.get("type") == "numeric" and case.get("ranges"):
                    start_n = _figure(cell)  # "| Factory | 35 |": within the case's range
                    if start_n is not None and any(
                        lo <= start_n <= hi for lo, hi, _ in case["ranges"]
                    ):
                        case["initial"] = start_n
        break


def _figure(cell: str) -> float | None:
    """The one figure a cell gives ("35", "8.0", "0,5"), or None; a unit after it is the
    column's own ("| Step | 10 °C |", "| Factory | 150 °C |")."""
    m = re.fullmatch(
        r"\s*(\d+(?:[.,]\d+)?)\s*(?:°\s*[cf]?|%|[a-zμ]{1,3}(?:/[a-z]{1,3})?)?\s*", cell, re.I
    )
    if not m:
        return None
    value = float(m.group(1).replace(",", "."))
    return int(value) if value.is_integer() else value


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
    if spec.get("type") not in ("time", "numeric"):
        return
    timed = spec.get("type") == "time"
    for c in range(1, len(header)):
        if c == column or not _STEP_HEAD_RE.search(header[c]):
            continue
        for row in rows:
            cell = _norm(row.cells[c]) if c < len(row.cells) else ""
            step = _duration(cell) if timed else _figure(cell)  # "| Step | 0.5 |"
            if not step:
                continue
            for target in _parent_values(row.cells[0], pvalues):
                case = cases.get(target)
                if not case or not case.get("ranges") or len(case["ranges"]) != 1:
                    continue
                lo, hi, _ = case["ranges"][0]
                a, b = (_seconds(lo), _seconds(hi)) if timed else (lo, hi)
                if b > a and round((b - a) / step, 6) % 1 == 0:
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
