"""A numbered mode named by what its row of the manual's code chart says: "from dusk till dawn"
for code 0 ("0  Dusk to dawn: on at dusk, off at dawn"), "test mode" for 16 ("16  Test mode:
…"), "five hours after dusk" for 5 ("5  On at dusk for 5 hours").

Controllers and timers show a mode only as its code; the chart says what each code does. A
chart counts when four or more lines in a row open with a code (or a span of codes, "8–14") the
same unitless numbered setting takes, and no other such setting does (or only it is named in
the lines above the chart). A row's label (the words before a colon) said in full picks its
code; a span of hours said, on a model with no setting of its own for time, picks the row that
runs so many hours ("8–14  … for 8 … 14 hours": the code is the hour), and "the longest" /
"the shortest" such row the one with most / fewest hours.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.domain import all_values
from apbot.model.schema import NumericVariable, TimeVariable
from apbot.read.goal_contents_lines import contents_cell
from apbot.read.goal_text import Text
from apbot.read.goal_view import Goal, Model, own_stems
from apbot.read.goal_vocab import STOP_WORDS, stem
from apbot.read.numbers import find_mentions

_ROW = re.compile(r"^\s*\|?\s*(\d{1,3})(?:\s*[–-]\s*(\d{1,3}))?\s*(?:\||\s{2,}|\t)\s*(\S.*)$")
_HOURS = re.compile(r"(\d{1,2})(?:\s*(?:…|\.\.\.|–|-|to)\s*(\d{1,2}))?\s*(?:hours?|h)\b")
_LABEL = re.compile(r"^([^:]{2,30}):")
_GENERIC = frozenset({stem(w) for w in ("mode", "setting", "programme", "program", "function")})
_ROWS = 4
_ABOVE = 4
_GAP = 2
_LONGEST = {"longest": max, "shortest": min}
Row = tuple[list[int], str]


def _blocks(lines: tuple[str, ...]) -> list[tuple[int, list[Row]]]:
    """Runs of code rows (a wrapped line between two rows is allowed): (first line, rows)."""
    blocks: list[tuple[int, list[Row]]] = []
    rows: list[Row] = []
    first = last = -10
    for k, line in enumerate(lines):
        row = _ROW.match(line)
        if row is None or contents_cell(row[3]):
            continue
        low = int(row[1])
        codes = list(range(low, int(row[2]) + 1)) if row[2] else [low]
        if k - last > _GAP or not codes or (rows and codes[0] <= rows[-1][0][-1]):
            if len(rows) >= _ROWS:
                blocks.append((first, rows))
            rows, first = [], k
        rows.append((codes, row[3]))
        last = k
    if len(rows) >= _ROWS:
        blocks.append((first, rows))
    return blocks


def _owner(view: Model, first: int, rows: list[Row]) -> str | None:
    codes = {c for row_codes, _ in rows for c in row_codes}
    owners = []
    for name, info in view.infos.items():
        var = info.var
        if info.role != "setting" or not isinstance(var, NumericVariable) or var.unit:
            continue
        try:
            if codes <= {int(float(v)) for v in all_values(var) if float(v).is_integer()}:
                owners.append(name)
        except (TypeError, ValueError):
            continue
    if len(owners) > 1:
        above = " ".join(view.manual_lines[max(0, first - _ABOVE) : first])
        words = {stem(w) for w in re.findall(r"[a-z]+", above)}
        owners = [n for n in owners if own_stems(view.infos[n]) & words]
    return owners[0] if len(owners) == 1 else None


def _charts(view: Model) -> list[tuple[str, list[Row]]]:
    found = []
    for first, rows in _blocks(view.manual_lines):
        owner = _owner(view, first, rows)
        if owner is not None:
            found.append((owner, rows))
    return found


def _hours(rows: list[Row]) -> dict[float, int]:
    """Hours -> code, for the rows that run a number of hours."""
    hours: dict[float, int] = {}
    for codes, said in rows:
        figures = _HOURS.findall(said)
        if len(figures) != 1:
            continue
        low, high = figures[0]
        if len(codes) == 1 and not high:
            hours.setdefault(float(low), codes[0])
        elif high and len(codes) == int(high) - int(low) + 1:
            for k, code in enumerate(codes):
                hours.setdefault(float(int(low) + k), code)
    return hours


def _times_itself(view: Model) -> bool:
    return any(
        isinstance(info.var, TimeVariable)
        or (isinstance(info.var, NumericVariable) and (info.var.unit or "") in ("s", "min", "h"))
        for info in view.infos.values()
    )


def coded_rows(
    view: Model, text: Text, goal: Goal, claimed: set[int], where: dict[str, int]
) -> None:
    """Set a charted mode by its row's label, hours, or the longest / shortest timed row."""
    for name, rows in _charts(view):
        if name in goal:
            continue
        found = _labelled(text, rows, claimed) or _timed(view, text, rows, claimed)
        if found is not None:
            code, start, taken = found
            goal[name] = code
            where[name] = start
            claimed.update(taken)


def _labelled(text: Text, rows: list[Row], claimed: set[int]) -> tuple[Any, int, set[int]] | None:
    free = {text.stems[k]: k for k in range(len(text.tokens)) if k not in claimed}
    best: tuple[int, Any, int, set[int]] | None = None
    for codes, said in rows:
        label = _LABEL.match(said)
        if label is None or len(codes) != 1:
            continue
        words = {stem(w) for w in re.findall(r"[a-z0-9]+", label[1]) if w not in STOP_WORDS}
        words -= _GENERIC
        if not words or not words <= free.keys():
            continue
        at = {free[w] for w in words}
        if best is None or len(words) > best[0]:
            best = (len(words), codes[0], min(at), at)
    return None if best is None else best[1:]


def _timed(
    view: Model, text: Text, rows: list[Row], claimed: set[int]
) -> tuple[Any, int, set[int]] | None:
    hours = _hours(rows)
    if len(hours) < 2 or _times_itself(view):
        return None
    for mention in find_mentions(text.tokens, skip=claimed):
        if mention.kind == "duration" and mention.value / 3600 in hours:
            return (
                hours[mention.value / 3600],
                mention.start,
                set(range(mention.start, mention.end)),
            )
    for k in range(len(text.tokens)):
        pick = _LONGEST.get(text.word(k).casefold())
        if k not in claimed and pick is not None:
            return hours[pick(hours)], k, {k}
    return None
