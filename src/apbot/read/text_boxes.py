"""Tables drawn with box characters, turned into pipe tables before the text is cleaned.

Manuals converted from a PDF, or laid out for a fixed-width page, draw their charts with box
characters: a top border with column marks (┌──┬──┐), rows between vertical bars (│ A1 │ …
│), a rule under the header (├──┼──┤), and a cell too long for its column wrapped onto the
next line with the other cells of that line left empty. Read character by character, the
bars become dashes and each drawn line a sentence of its own, so a programme chart loses its
columns and a key table its rows. Here a box with column marks becomes the pipe table it
draws: the bars become pipes, a rule becomes a Markdown rule, and a line whose first cell is
empty continues the row above, cell by cell. A box without column marks (a drawing of the
panel) is left as it is. Lines keep their numbers (a line merged into the row above becomes a
rule line the table reader passes over), so the report still quotes the right line.
"""

from __future__ import annotations

import re

_TOP = re.compile(r"^\s*┌[─━┬]*┬[─━┬]*┐\s*$")  # a top border with column marks
_RULE = re.compile(r"^\s*[├╞┝][─━═┼╪┿]*[┤╡┥]\s*$")
_BOTTOM = re.compile(r"^\s*└[─━┴]*┘\s*$")
_ROW = re.compile(r"^\s*│.*│\s*$")
# the same box typed in ASCII ("+------+----+", "| A1 | … |"): every border is the same line
_GRID = re.compile(r"^\s*\+(?:[-=]{2,}\+){2,}\s*$")
_GRID_ROW = re.compile(r"^\s*\|.*\|\s*$")
# a box drawn with double lines (╔══╦══╗, ║ A1 ║ … ║, ╠══╬══╣) is the same table: read as single
_SINGLE = str.maketrans("╔╦╗╠╬╣╚╩╝║═", "┌┬┐├┼┤└┴┘│─")


def _cells(line: str, bar: str = "│") -> list[str]:
    cells = [c.strip() for c in line.strip().strip(bar).split(bar)]
    if bar != "|":  # a sign drawn with a bar ("▶|" for a diode) is no column: the broken bar
        cells = [c.replace("|", "¦") for c in cells]  # keeps the pipe table's columns whole
    return cells


def _rule(width: int) -> str:
    return "|" + "---|" * width


def unbox(text: str) -> str:
    """``text`` with every box table that has column marks written as a pipe table."""
    lines = text.translate(_SINGLE).split("\n")
    k = 0
    while k < len(lines):
        if _GRID.match(lines[k]):
            k = _grid(lines, k)
            continue
        if not _TOP.match(lines[k]):
            k += 1
            continue
        end = k + 1
        while end < len(lines) and (_ROW.match(lines[end]) or _RULE.match(lines[end])):
            end += 1
        if end >= len(lines) or not _BOTTOM.match(lines[end]) or end == k + 1:
            k = end
            continue
        _rewrite(lines, k, end)
        k = end + 1
    return "\n".join(lines)


def _grid(lines: list[str], top: int) -> int:
    """The ASCII box whose top border is line ``top``, rewritten as :func:`_rewrite` does (its
    last border is the bottom, the ones between are rules); the line to go on from."""
    end = top + 1
    while end < len(lines) and (_GRID_ROW.match(lines[end]) or _GRID.match(lines[end])):
        end += 1
    bottom = end - 1
    while bottom > top and not _GRID.match(lines[bottom]):
        bottom -= 1
    if bottom - top < 2 or not any(_GRID_ROW.match(lines[i]) for i in range(top, bottom)):
        return top + 1
    _rewrite(lines, top, bottom, bar="|", rule=_GRID, row=_GRID_ROW)
    return bottom + 1


def _ruled_rows(
    lines: list[str], inside: range, first_rule: int | None, rule: re.Pattern[str]
) -> bool:
    """Whether the rules below the header close each row ("+----+" under every key of a grid):
    most runs of lines between two rules are one line, so a run of two or more is one row
    wrapped ("CHILD" over "LOCK"), even when its second line fills the first cell."""
    if first_rule is None:
        return False
    runs: list[int] = []
    count = 0
    for i in range(first_rule + 1, inside.stop):
        if rule.match(lines[i]):
            runs.append(count)
            count = 0
        else:
            count += 1
    runs.append(count)
    runs = [n for n in runs if n]
    return len(runs) >= 3 and 2 * sum(n == 1 for n in runs) > len(runs)


# a short item of its own, no wrapped text: a code, a number, a one-word name ("N2", "15", "P-3")
_ITEM = re.compile(r"[A-Z]{0,3}[-.]?\d{1,3}[a-z]?|[A-Z][A-Z0-9-]{0,7}")


def _spanned(above: list[str], cells: list[str]) -> bool:
    """Whether a line with an empty first cell is a row of its own under a label spanning the
    rows of its group (the first cell drawn once for the group), not a wrap: every other cell
    is filled, and its second holds an item of the same shape as the row above's second."""
    if cells[0] or len(cells) < 3 or not all(cells[1:]) or not all(above):
        return False
    return bool(_ITEM.fullmatch(cells[1]) and _ITEM.fullmatch(above[1]))


def _rewrite(
    lines: list[str],
    top: int,
    bottom: int,
    bar: str = "│",
    rule: re.Pattern[str] = _RULE,
    row: re.Pattern[str] = _ROW,
) -> None:
    """Lines ``top``..``bottom`` (the borders) of one box table, rewritten in place. Header
    lines above the table's rule stay rows of their own (the table reader joins a header
    written on two lines); below it, a wrapped line joins its row and becomes a rule line the
    reader passes over. A box with no rule gets one under its first row, that row moving up
    onto the top border's line, so its wrapped lines can be passed over too."""
    inside = range(top + 1, bottom)
    width = max(len(_cells(lines[i], bar)) for i in inside if row.match(lines[i]))
    first_rule = next((i for i in inside if rule.match(lines[i])), None)
    ruled = _ruled_rows(lines, inside, first_rule, rule)
    rules = {i for i in inside if rule.match(lines[i])}
    rows: list[tuple[int, list[str]]] = []  # (line index, cells) of each row started
    for i in inside:
        if rule.match(lines[i]):
            lines[i] = _rule(width)
            continue
        cells = (_cells(lines[i], bar) + [""] * width)[:width]
        in_header = first_rule is not None and i < first_rule
        # under rules that close every row, a line right under another is its row's wrap
        wrapped = not cells[0] or (ruled and i - 1 not in rules)
        if rows and wrapped and not ruled and _spanned(rows[-1][1], cells):
            cells[0] = rows[-1][1][0]  # "│ │ N2 │ Ocean waves │": a row under a group's label
            wrapped = False
        if rows and wrapped and any(cells) and not in_header:
            last = rows[-1][1]
            for c, cell in enumerate(cells):
                if cell:
                    last[c] = f"{last[c]} {cell}".strip()
            lines[i] = _rule(width)
            continue
        rows.append((i, cells))
    if first_rule is None and rows:  # the first row up one line, a rule under it
        rows[0] = (top, rows[0][1])
        lines[top + 1] = _rule(width)
    else:
        lines[top] = ""
    for i, cells in rows:
        lines[i] = "| " + " | ".join(cells) + " |"
    lines[bottom] = ""
