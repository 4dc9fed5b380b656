"""A dial's numbered positions that a chart turns into amounts: "Position | Display | Current"
over "0 | C0 | 6 A", "1 | C1 | 8 A", … ("The position number is not the current in amperes -
look it up in the chart below").

A coded selector has positions 0 … 7 printed on it, and the manual charts what each position
gives. The user asks for the amount ("charge at 20 amps"), never the position, so a setting
read as the bare positions takes the chart's amounts as its values, in the column the setting
is named in (else the only column of one unit), and the chart's code column as what the
display shows for each.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import tidy_number
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.values import gap_pieces, number

_POSITION_HEAD = re.compile(
    r"^\W*(?:position|pos\.?)\W*$", re.I
)  # not "Setting", "No.": a row number
_AMOUNT = re.compile(r"^\s*(\d+(?:[.,]\d+)?)\s*([A-Za-z%°][\w°/%]{0,4})\s*$")
_CODE = re.compile(r"^\s*([A-Za-z]{1,3}-?\d{1,3})\s*$")


def read_position_charts(b: Builder) -> None:
    """Give a setting read as its dial's bare positions the amounts its chart lists for them."""
    units = b.manual.units
    for var, spec in b.variables.items():
        ranges = spec.get("ranges") or []
        if spec.get("type") != "numeric" or spec.get("unit") or len(ranges) != 1:
            continue
        low, high, step = ranges[0]
        if step != 1 or not float(low).is_integer() or not 2 <= high - low <= 20:
            continue
        positions = [str(p) for p in range(int(low), int(high) + 1)]
        own = {w[:5] for w in words(var.replace("_", " ")) + words(str(spec.get("label", "")))}
        for i in range(len(units)):
            table = _table_at(units, i)
            if table is None:
                continue
            header, rows = table
            if [r.cells[0].strip() for r in rows] != positions:
                continue
            found = _chart(header, rows, own)
            if found is None:
                continue
            amounts, unit_text, codes = found
            pieces = gap_pieces(amounts, unit_text)
            spec["ranges"] = [
                [tidy_number(r.low), tidy_number(r.high), tidy_number(r.step or 1)] for r in pieces
            ]
            spec["unit"] = unit_text
            if codes:
                spec["show"] = {f"{a:g}": c for a, c in zip(amounts, codes, strict=True)}
            spec.pop("initial", None)
            b.unread.discard(var)
            b.note(f"variables.{var}", f"the chart's {unit_text} for each position", i)
            break


def _table_at(units: list[Any], i: int) -> tuple[tuple[str, ...], list[Any]] | None:
    """The chart whose head is unit ``i``: its header and rows. A head line the text reader
    took for a sentence ("Position   Display   Current …" over a rule) makes the first row the
    table's header; then the head is split at its wide gaps and that row is a row again."""
    unit = units[i]
    if unit.cells and not unit.header and len(unit.cells) >= 3:
        if _POSITION_HEAD.match(unit.cells[0]):
            return unit.cells, [u for u in units[i + 1 :] if u.header == unit.cells and u.cells]
        return None
    if unit.cells or i + 1 >= len(units):
        return None
    head = tuple(re.split(r"\s{2,}", unit.text.strip()))
    first = units[i + 1]
    if len(head) < 3 or not _POSITION_HEAD.match(head[0]) or not first.cells or first.header:
        return None
    rows = [first] + [u for u in units[i + 2 :] if u.header == first.cells and u.cells]
    return head, rows


def _chart(
    header: tuple[str, ...], rows: list[Any], own: set[str]
) -> tuple[list[float], str, list[str]] | None:
    """The amounts (climbing, one unit) of the column naming the setting, or of the only such
    column, and the codes of a code column ([] when none)."""
    columns: list[tuple[int, list[float], str]] = []
    codes: list[str] = []
    for c in range(1, len(header)):
        cells = [r.cells[c] if c < len(r.cells) else "" for r in rows]
        read = [_AMOUNT.match(x) for x in cells]
        if all(read):
            read_figures = [number(m.group(1)) for m in read if m]
            figures = [f for f in read_figures if f is not None]
            units = {m.group(2) for m in read if m}  # (as printed: "A", not a unit's name)
            if len(units) == 1 and len(figures) == len(rows) and figures == sorted(set(figures)):
                columns.append((c, figures, units.pop()))
        elif all(_CODE.match(x) for x in cells) and len(set(cells)) == len(cells) and not codes:
            codes = [x.strip() for x in cells]
    named = [col for col in columns if {w[:5] for w in words(header[col[0]])} & own]
    chosen = named or (columns if len(columns) == 1 else [])
    if not chosen:
        return None
    _, amounts, unit_text = chosen[0]
    return amounts, unit_text, codes
