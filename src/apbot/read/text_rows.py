"""Pipe-table rows as a PDF's text leaves them: a rule drawn with "+" at the column joints, and
a row whose cells wrapped onto a line of their own.

A table printed with bars between its columns often comes out of the conversion with its rule
drawn as dashes crossed by plus signs ("-------+--------+------") instead of bars. That line
is the table's rule all the same: the lines above it are the header (one header row, however
many lines it takes), the lines under it are rows. Read as prose, it ends the table, and the
first data row is taken for the header of the rest.

A cell too long for its column wraps onto the next line, and that line holds nothing but the
wrapped ends ("100 | 0 | black tea, herbal tea," then "    |   | instant soups, pasta"): a row
with more cells empty than filled, each filled cell under a filled cell of the row above that
runs on to it (a comma, a hyphen, a word that needs one more, or a word in lower case outside
the first column, whose lower-case words name rows of their own: "eco", then "boost"). It
belongs to the row above, cell by cell; read as a row of its own it is a row of blanks, which
ends a chart's run of levels and adds nothing a setting could be.
"""

from __future__ import annotations

import re

from apbot.read.text_pages import OPEN_ENDS

# a rule with "+" at the joints: "------+------+-----", "+-----+-----+", ":---+---:"
GRID_RULE = re.compile(r"^\s*\+?\s*:?-{2,}:?\s*(?:\+\s*:?-{2,}:?\s*)+\+?\s*$")

# the end of a cell that runs on onto the next line: a comma, a hyphen, an opening bracket, or
# a word that needs the next one ("for", "in", "and", "the" …: text_pages.OPEN_ENDS)
_RUNS_ON_MARK = re.compile(r"[,(/&+-]$")


def _runs_on(cell: str) -> bool:
    """Whether ``cell`` stops where its text cannot end."""
    last = re.search(r"\w+$", cell)
    return bool(_RUNS_ON_MARK.search(cell)) or bool(last and last.group(0).lower() in OPEN_ENDS)


def _continues(above: str, below: str, lead: bool = False) -> bool:
    """Whether ``below`` goes on with the cell ``above`` (its wrapped end). In the first
    column (``lead``), which names each row, a word in lower case is the next row's name
    ("eco" then "boost"): only a cell that needs more runs on there."""
    runs_on = _runs_on(above)
    return bool(above) and (runs_on or (below[:1].islower() and not lead))


def wrapped_cells(above: tuple[str, ...], row: tuple[str, ...]) -> tuple[str, ...] | None:
    """The row above with ``row``'s wrapped ends joined on, when ``row`` is only that: more of
    its cells empty than filled, each filled one running on from the cell above it. None when
    ``row`` is a row of its own."""
    if len(row) > len(above) or not above:
        return None
    row = row + ("",) * (len(above) - len(row))  # (the empty cells at the end left out)
    filled = [k for k, cell in enumerate(row) if cell]
    if not filled or len(filled) * 2 > len(row):
        return None
    if not all(_continues(above[k], row[k], k == 0) for k in filled):
        return None
    merged = list(above)
    for k in filled:
        glue = "" if re.search(r"\w-$", above[k]) else " "  # "pour-" + "over)": one word
        merged[k] = f"{above[k]}{glue}{row[k]}"
    return tuple(merged)
