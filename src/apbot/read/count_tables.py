"""Charts of what the display reads after so many presses or clicks: a setting's whole range.

Some manuals give a setting's values by example only: a table whose one column counts the
touches or clicks from the start ("Touches of +", "Clicks clockwise", "Clicks anticlockwise")
and whose next column is what the display then reads ("| 1 | 300 ml |", "| 14 | PRESET 7:00 |",
"| 8 or more | 100°C |"). Rows may skip counts; a row "N or more" is where the setting stops.
Read between the rows, the counts give the step (two clicks from 300 ml to 500 ml: 100 ml a
click) and where the step changes, so the chart is the setting's piecewise range with its steps.
The start is the row counting 0, or the caption's "start: 250 ml" / "from PRESET 0:00".
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass

from apbot.read.text import Unit
from apbot.read.values import Range, number, unit_name

# the head of a column counting presses or clicks ("Touches of +", "Clicks clockwise", "Presses")
_COUNT_HEAD_RE = re.compile(
    r"^(?:no\.?\s+of\s+|number\s+of\s+)?(?:press(?:es)?|touch(?:es)?|taps?|clicks?|turns?)\b"
    r"(?P<rest>.{0,30})$",
    re.IGNORECASE,
)
_DOWN_RE = re.compile(r"anti-?clockwise|counter-?clockwise|\bdown\b|[−▼-]|minus|\bback", re.I)
_COUNT_CELL_RE = re.compile(r"^(\d{1,3})(\s+or\s+more)?$", re.IGNORECASE)
# a display reading: an optional label in capitals, then an amount or a clock figure
_UNITS = r"°\s?[CF]|ml|mL|l|L|g|kg|%|W|rpm"
_READING_RE = re.compile(
    r"^(?P<label>[A-Z][A-Z ]*?\s+)?(?:(?P<clock>\d{1,2}:[0-5]\d)"
    rf"|(?P<num>\d+(?:[.,]\d+)?)\s*(?P<unit>{_UNITS}))$"
)
_START_RE = re.compile(r"\b(?:start(?:s|ing)?|from)\b", re.IGNORECASE)


@dataclass(frozen=True)
class CountChart:
    """A chart read: its pieces, the label its readings carry ("PRESET") or "", the head
    naming what is counted ("Touches of +"), and the index of its first row."""

    pieces: list[Range]
    label: str
    heads: tuple[str, ...]
    at: int


def _reading(cell: str) -> tuple[str, float, str] | None:
    """A display reading's label, amount and unit ("PRESET 7:00" → PRESET, 25200, s)."""
    m = _READING_RE.match(cell.strip())
    if not m:
        return None
    label = (m.group("label") or "").strip()
    if m.group("clock"):
        hours, minutes = m.group("clock").split(":")
        return label, int(hours) * 3600 + int(minutes) * 60, "s"
    amount = number(m.group("num"))
    return (label, amount, unit_name(m.group("unit"))) if amount is not None else None


_COUNTS_RE = re.compile(r"\d{1,3}(?:\s+or\s+more)?", re.IGNORECASE)
_READINGS_RE = re.compile(  # readings one after another in a cell ("TIME 1:00 TIME 1:10")
    rf"(?:[A-Z][A-Z ]*?\s+)?(?:\d{{1,2}}:[0-5]\d|\d+(?:[.,]\d+)?\s*(?:{_UNITS}))"
)


def _cell_pairs(
    count_cell: str, reading_cell: str
) -> list[tuple[re.Match[str], tuple[str, float, str]]]:
    """A count cell and its reading, or two rows the layout ran into one cell ("36 37 or
    more" beside "PRESET 24:00 PRESET 24:00"): pairs of a count and a reading, [] when not."""
    said = _COUNTS_RE.findall(count_cell)
    if " ".join(said) != " ".join(count_cell.split()):
        return []
    counts = [_COUNT_CELL_RE.match(c) for c in said]
    readings = [_reading(r) for r in _READINGS_RE.findall(reading_cell)]
    pairs = [(c, r) for c, r in zip(counts, readings, strict=False) if c and r]
    return pairs if len(pairs) == len(counts) == len(readings) else []


def _start(units: list[Unit], k: int, unit: str) -> float | None:
    """The start the caption above a chart gives ("Table 2 – Quantity (start: 250 ml)",
    "How the preset moves – clicks clockwise from PRESET 0:00")."""
    for j in range(k - 1, max(k - 3, -1), -1):
        if units[j].cells:
            break
        text = units[j].text
        m = _START_RE.search(text)
        if not m:
            continue
        for word in re.split(r"[\s,;()]+(?=[A-Z\d])", text[m.end() :]):
            read = _reading(word.strip(" .,;:)"))
            if read and read[2] == unit:
                return read[1]
        for token in re.findall(r"\d{1,2}:[0-5]\d|\d+(?:[.,]\d+)?\s*[^\s\d,;()]+", text[m.end() :]):
            read = _reading(token)
            if read and read[2] == unit:
                return read[1]
    return None


def _pieces(points: dict[int, float], unit: str) -> list[Range]:
    """Pieces of equal step through points keyed by signed count (0 the start)."""
    counts = sorted(points)
    values = [points[c] for c in counts]
    if any(b <= a for a, b in itertools.pairwise(values)):
        return []
    pieces: list[Range] = []
    for (c0, v0), (c1, v1) in itertools.pairwise(zip(counts, values, strict=True)):
        step = round((v1 - v0) / (c1 - c0), 6)
        if step <= 0 or abs(step * (c1 - c0) - (v1 - v0)) > 1e-6:
            return []
        if pieces and abs((pieces[-1].step or 0) - step) < 1e-9:
            pieces[-1] = Range(pieces[-1].low, v1, unit, step)
        else:
            pieces.append(Range(v0, v1, unit, step))
    return pieces


def _stretched(pieces: list[Range], ends: list[float]) -> list[Range]:
    """The pieces carried on to a stop the chart gives past its last counted row ("9 or more
    | 1000 ml" after "5 | 700 ml", rows between left out) when the step reaches it."""
    if not pieces:
        return pieces
    out = list(pieces)
    for end in ends:
        first, last = out[0], out[-1]
        if end > last.high and last.step and _whole((end - last.high) / last.step):
            out[-1] = Range(last.low, end, last.unit, last.step)
        elif end < first.low and first.step and _whole((first.low - end) / first.step):
            out[0] = Range(end, first.high, first.unit, first.step)
    return out


def _whole(x: float) -> bool:
    return abs(x - round(x)) < 1e-6


def count_charts(units: list[Unit]) -> list[CountChart]:
    """Every chart of counted presses or clicks and display readings, read into pieces."""
    out: list[CountChart] = []
    k = 0
    while k < len(units):
        head = units[k].cells
        if not head or units[k].header:
            k += 1
            continue
        pairs = [
            (c, bool(_DOWN_RE.search(m.group("rest"))))
            for c in range(len(head) - 1)
            if (m := _COUNT_HEAD_RE.match(head[c].strip()))
        ]
        rows = []
        j = k + 1
        while j < len(units) and units[j].header == head:
            rows.append(units[j].cells)
            j += 1
        chart = _read_chart(units, k, head, pairs, rows) if pairs and rows else None
        if chart:
            out.append(chart)
        k = max(j, k + 1)
    return out


def _read_chart(
    units: list[Unit],
    k: int,
    head: tuple[str, ...],
    pairs: list[tuple[int, bool]],
    rows: list[tuple[str, ...]],
) -> CountChart | None:
    """One chart's pieces, or None where a cell is no count or no reading of one unit."""
    points: dict[int, float] = {}
    ends: list[float] = []
    labels: set[str] = set()
    units_seen: set[str] = set()
    cells = bad = 0
    for row in rows:
        for c, down in pairs:
            if c + 1 >= len(row) or not row[c].strip():
                continue
            cells += 1
            found = _cell_pairs(row[c], row[c + 1])
            if not found:
                bad += 1
                continue
            for count, read in found:
                labels.add(read[0])
                units_seen.add(read[2])
                if count.group(2):
                    ends.append(read[1])  # "8 or more": where the setting stops
                    continue
                n = int(count.group(1)) * (-1 if down else 1)
                if points.get(n, read[1]) != read[1]:
                    return None
                points[n] = read[1]
    if len(units_seen) != 1 or len(labels) != 1 or len(points) < 3 or 4 * bad > cells:
        return None
    unit = units_seen.pop()
    if 0 not in points and (start := _start(units, k, unit)) is not None:
        points[0] = start
    pieces = _stretched(_pieces(points, unit), ends)
    if not pieces:
        return None
    heads = tuple(head[c] for c, _ in pairs)
    return CountChart(pieces, labels.pop(), heads, k)


# a sideways chart's first line: what is counted, then the counts ("touches   1   2   3   …   14",
# "Presses of END TIME    1     2  …  18"); the next line gives the readings in the same order
_COUNT_ROW_RE = re.compile(
    r"^\s*(?P<head>(?:no\.?\s+of\s+|number\s+of\s+)?(?:press(?:es)?|touch(?:es)?|taps?|clicks?)"
    r"\b[^\d…]{0,30}?)\s{2,}(?P<counts>\d{1,3}(?:\s+(?:\d{1,3}|…|\.\.\.))+)\s*$",
    re.IGNORECASE,
)


def sideways_charts(units: list[Unit], lines: list[str]) -> list[CountChart]:
    """Charts printed sideways, a line of counts over a line of readings ("touches  1  2  …
    14" over "weight  100 g 200 g … 2000 g"), read from the lines as printed (single spaces
    inside the readings defeat a table's columns); an ellipsis stands in both lines alike.
    A last reading that falls back below the one before ("… 19 h 0 h") is the wrap to off."""
    out: list[CountChart] = []
    for n, line in enumerate(lines[:-1]):
        m = _COUNT_ROW_RE.match(line)
        if not m:
            continue
        counts = [int(c) for c in re.findall(r"\d{1,3}", m.group("counts"))]
        readings = [_reading(r) for r in _READINGS_RE.findall(lines[n + 1])]
        said = [r for r in readings if r]
        if len(said) != len(counts) or len({(r[0], r[2]) for r in said}) != 1:
            continue
        if len(said) >= 2 and said[-1][1] < said[-2][1]:
            counts, said = counts[:-1], said[:-1]
        points = {c: r[1] for c, r in zip(counts, said, strict=True)}
        pieces = _pieces(points, said[0][2]) if len(points) >= 3 else []
        at = [k for k, u in enumerate(units) if u.line <= n + 1]
        if pieces and at:
            out.append(CountChart(pieces, said[0][0], (m.group("head").strip(),), at[-1]))
    return out


def chart_for(
    charts: list[CountChart],
    own: set[str],
    turned: bool,
    other_turned: bool,
    context: list[int],
) -> CountChart | None:
    """The chart about a control: its readings carry the control's label ("PRESET 7:00" for
    PRESET), or, unlabelled, its head names the control ("Touches of +"), counts clicks of
    the panel's only dial when that is the control (``turned``, no ``other_turned``) or
    counts bare touches right after a sentence about the control (in its ``context``)."""
    for chart in charts:
        if chart.label:
            if chart.label.upper() in own:
                return chart
            continue
        heads = " ".join(chart.heads)
        if any(re.search(rf"(?<!\w){re.escape(lab)}(?!\w)", heads) for lab in own if lab):
            return chart
        dial = turned and not other_turned and re.search(r"clicks?|turns?", heads, re.I)
        if dial and not re.search(r"\bof\b", heads):  # ("Touches of +": that key's)
            return chart
        near = chart.at in context or chart.at - 1 in context  # (the sentence before it)
        if near and not re.search(r"\bof\b", heads):  # ("touches": its own)
            return chart
    return None
