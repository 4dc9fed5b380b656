"""HTML tables in a manual: rows with cells, as a pipe table's would be.

A vision model converting a PDF often writes a table as HTML (``<table><tr><td>ON/OFF</td>
<td>Switch …</td></tr>…``), one row per line or spread over many. Read as text, every row of a
key legend would run into the next as one sentence. Here each ``<tr>`` becomes one row of
cells (``<br>``, inline tags and entities cleaned), kept at the line where the row starts so
the reading report still quotes the right line; the table's other lines (the tags alone) are
left out. A row whose cells are all ``<th>`` is the header; as in a pipe table, a table with
none takes its first row as the header.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass, field

_TABLE_OPEN = re.compile(r"<table\b[^>]*>", re.IGNORECASE)
_TABLE_CLOSE = re.compile(r"</table\s*>", re.IGNORECASE)
_ROW = re.compile(r"<tr\b[^>]*>(.*?)(?=<tr\b|</tr\s*>|</table\s*>|\Z)", re.IGNORECASE | re.DOTALL)
_CELL = re.compile(
    r"<t([dh])\b([^>]*)>(.*?)(?=<t[dh]\b|</t[dh]\s*>|</tr\s*>|\Z)", re.IGNORECASE | re.DOTALL
)
_TABLE_TAG = re.compile(r"</?(?:t[rdh]|thead|tbody|tfoot|caption)\b", re.IGNORECASE)
_SPAN = re.compile(r"colspan\s*=\s*[\"']?(\d+)", re.IGNORECASE)
_BREAK = re.compile(r"<br\s*/?>", re.IGNORECASE)
_TAG = re.compile(r"</?[a-zA-Z][^>]*>")
MAX_SPAN = 12  # a wider colspan is a layout trick, not so many columns


@dataclass
class HtmlTables:
    """Where HTML tables put rows: line index → rows starting there; lines to leave out;
    lines where a table starts (a pipe header above does not run on into it)."""

    rows: dict[int, list[tuple[tuple[str, ...], bool]]] = field(default_factory=dict)
    skipped: set[int] = field(default_factory=set)
    starts: set[int] = field(default_factory=set)


_EDGE = re.compile(r"(?=<table\b)|(?<=</table>)", re.IGNORECASE)


def tables_apart(lines: list[str], numbers: list[int]) -> tuple[list[str], list[int]]:
    """The lines with a table's start and end each beginning and ending a line of its own (at
    the same line number): "Keys: <table>…</table> Press START to boil." keeps "Keys:" and the
    sentence after the table as text, instead of losing them with the table's tag lines."""
    out: list[str] = []
    outnums: list[int] = []
    for line, number in zip(lines, numbers, strict=True):
        pieces = [line]
        if "table" in line.casefold():
            pieces = [x for x in _EDGE.split(line) if x.strip()] or [line]
        out.extend(pieces)
        outnums.extend([number] * len(pieces))
    return out, outnums


def html_tables(lines: list[str]) -> HtmlTables:
    """The HTML tables of ``lines`` (see the module docstring)."""
    found = HtmlTables()
    k = 0
    while k < len(lines):
        opened = _TABLE_OPEN.search(lines[k])
        if not opened:
            k += 1
            continue
        end = k
        while end < len(lines) and not _TABLE_CLOSE.search(
            lines[end], opened.end() if end == k else 0
        ):
            end += 1
        if end == len(lines):  # never closed: the table is the run of lines with its tags
            end = k
            while end + 1 < len(lines) and _TABLE_TAG.search(lines[end + 1]):
                end += 1
        _read_table(lines, k, end, opened.start(), found)
        k = end + 1
    return found


def _read_table(lines: list[str], first: int, last: int, column: int, found: HtmlTables) -> None:
    """Rows of the table on lines ``first``..``last`` (its tag at ``column`` of the first)."""
    offsets: list[int] = []
    text = ""
    for k in range(first, last + 1):
        offsets.append(len(text))
        text += (lines[k][column:] if k == first else lines[k]) + "\n"
    rows = 0
    for row in _ROW.finditer(text):
        cells = _cells(row.group(1))
        if not cells or not any(c for c, _ in cells):
            continue
        line = first + max(i for i, off in enumerate(offsets) if off <= row.start())
        heads = all(kind == "h" for _, kind in cells)
        found.rows.setdefault(line, []).append((tuple(c for c, _ in cells), heads))
        rows += 1
    if not rows:
        return  # no row at all: the tags were words in running text, left as they are
    found.starts.add(first)
    found.skipped.update(k for k in range(first, last + 1) if k not in found.rows)


def _cells(row: str) -> list[tuple[str, str]]:
    """A row's cells, each (text, "d" or "h"), repeated over the columns it spans."""
    cells: list[tuple[str, str]] = []
    for cell in _CELL.finditer(row):
        content = _TAG.sub(" ", _BREAK.sub(" ", cell.group(3)))
        content = re.sub(r"\s+", " ", html.unescape(content)).strip().replace("|", "/")
        span = _SPAN.search(cell.group(2))
        width = min(int(span.group(1)), MAX_SPAN) if span else 1
        cells.extend([(content, cell.group(1).lower())] * max(width, 1))
    return cells
