"""Reading a table's column or a run of bullets right after a unit: the cells of one column
(names, durations), a first column of ranges carried over rows, a row's step, whether a row is
a header. Apart from shapes.py because these walk the units that follow a sentence, while
shapes.py holds the words and one-unit tests the reader matches against."""

from __future__ import annotations

import re

from apbot.read.fault_tables import fault_table
from apbot.read.table_transposed import sideways_choices
from apbot.read.text import Unit
from apbot.read.value_steps import find_step
from apbot.read.values import Range, find_ranges

# a table's first column counting the presses ("| Presses | Menu |", "| Times pressed | Level |")
PRESSES_RE = re.compile(
    r"^\W*(?:no\.? of |number of )?(?:press(?:es)?|touch(?:es)?|taps?|times?)(?: pressed)?\b",
    re.I,
)


def _rows_span(units: list[Unit], i: int, first: Range) -> Range:
    """A range in a table's first column that the next rows carry on ("| 1 – 2 | … |",
    "| 3 – 4 | … |" … "| 9 – 10 | … |"): the rows are groups of one setting, whose whole span
    runs from the first row's low to the last row's high (a gap wider than the step, or than 1
    where none is given, ends it)."""
    own = find_ranges(units[i].cells[0])
    if len(own) != 1 or (own[0].low, own[0].high) != (first.low, first.high):
        return first
    last = first
    for row in units[i + 1 :]:
        if not row.cells or row.header != units[i].header:
            break
        nxt = find_ranges(row.cells[0])
        gap = nxt[0].low - last.high if len(nxt) == 1 and nxt[0].unit == first.unit else -1.0
        if not 0 < gap <= max(1.0, first.step or 0.0):
            break
        last = nxt[0]
    return first if last is first else Range(first.low, last.high, first.unit, first.step)


def _row_step(cells: tuple[str, ...], unit: str) -> float | None:
    """A table row's step: a cell that is one quantity ("half an hour", "5 min", "1 h")."""
    from apbot.model.values import parse_quantity

    for cell in cells[1:]:
        if find_ranges(cell):
            continue
        step = find_step(cell)
        if step:
            return step[0]
        q = parse_quantity(cell.strip().lower())  # ("half an hour": 30 min, not 1 h 30)
        if q and q[1] == "time" and q[0] > 0:
            base = {"s": 1, "min": 60, "h": 3600}.get(unit, 0)
            return q[0] / base if base else None
    return None


def _header_row(units: list[Unit], i: int) -> bool:
    """A table's header row (rows follow under it): the names of its columns, not values."""
    unit = units[i]
    return (
        bool(unit.cells)
        and not unit.header
        and i + 1 < len(units)
        and units[i + 1].header == unit.cells
        and sum(c.upper() == c for c in unit.cells) < len(unit.cells)  # not a row of key names
        and all(len(c) <= 24 for c in unit.cells)  # not two columns of prose side by side
    )


_AMOUNT_CELL_RE = re.compile(
    r"\d+(?:[.,]\d+)?\s*(?:h|hrs?|hours?|min|mins|s|sec|°[CF]|%|W|g|kg|ml|l|lb)"
)


def _next_table_column(units: list[Unit], i: int, column: int = 0) -> list[str]:
    """The cells of one column (the first by default) of the table that starts right after
    unit ``i`` (header skipped)."""
    k = i + 1
    shown = headless = False
    if column == 0 and k < len(units) and units[k].cells and not units[k].header:
        sideways = sideways_choices(units, k)
        if sideways:  # "| Mode | Sprout | Greens |" over rows of one unit each: the choices
            return sideways
    if k < len(units) and units[k].cells and not units[k].header:
        if column == 0 and len(units[k].cells) >= 2 and PRESSES_RE.match(units[k].cells[0]):
            column = 1  # the first column counts presses: the values are in the next one
        cells = units[k].cells
        headless = _data_first_row(units, k)
        if column == 0 and _drawn_column(units, k if headless else k + 1):
            column = 1  # "| ● ○ ○ | 2700 K |": lamps drawn as the display shows each value
        shown = column < len(cells) and bool(_DISPLAY_HEAD_RE.match(cells[column]))
        if not headless:
            k += 1  # the header row
    items: list[str] = []
    numbers = 0
    start = k
    while k < len(units) and units[k].cells and (units[k].header or (headless and k == start)):
        if column >= len(units[k].cells):
            k += 1
            continue
        cell = units[k].cells[column].strip(" *")
        if not _AMOUNT_CELL_RE.fullmatch(cell):  # "1 h" is an amount, "1  Basic" a numbered name
            cell = re.sub(r"^\s*\d{1,2}[.)]?\s+(?=\D)", "", cell).strip(" *")
        # "Meat (joints, steaks, minced meat)": the name before its gloss
        cell = re.sub(r"(?<=\w)\s*\([^)]*\)\s*$", "", cell)
        if find_ranges(cell) or not re.search(r"[A-Za-z]", cell) or _AMOUNT_CELL_RE.fullmatch(cell):
            numbers += 1
        if cell and len(cell) <= 24 and cell not in items:
            items.append(cell)
        k += 1
    if shown:
        items = _without_display_word(items)
    if k > start and fault_table(units[start].header, [u.cells for u in units[start:k]], column):
        return []  # "E1 | Sensor fault": the codes of faults, no setting's values
    if numbers * 2 > len(items):
        return []  # a column of ranges or bare numbers is not a list of names
    return items if len(items) >= 2 else []


def _drawn_column(units: list[Unit], k: int) -> bool:
    """Whether the first column of the table rows from unit ``k`` on is only drawn signs (lamps
    lit and dark, bars, dots: no letter or digit in any cell) beside a further column: such a
    column pictures each row's value as the panel shows it, so the value is the next cell (the
    reader's text drops such signs, leaving the cells empty)."""
    cells = []
    while k < len(units) and units[k].cells and units[k].header:
        if len(units[k].cells) < 2:
            return False
        cells.append(units[k].cells[0].strip(" *`"))
        k += 1
    return len(cells) >= 2 and all(not re.search(r"\w", c) for c in cells)


_FIGURE_CELL_RE = re.compile(r"\d[\d.,]*\s*[A-Za-z°%]{0,3}")


def _data_first_row(units: list[Unit], k: int) -> bool:
    """A table drawn without a header ("WARM  3000K  yellowish …" then "NEUTRAL  4500K …"):
    its first row holds a figure where every row below holds one in the same column, and a
    header names its columns with words ("Colour | Kelvin"), never with figures."""
    rows = []
    j = k + 1
    while j < len(units) and units[j].cells and units[j].header == units[k].cells:
        rows.append(units[j].cells)
        j += 1
    first = units[k].cells
    if len(rows) < 2:
        return False
    return any(
        _FIGURE_CELL_RE.fullmatch(first[c].strip())
        and all(c < len(r) and _FIGURE_CELL_RE.fullmatch(r[c].strip()) for r in rows)
        for c in range(len(first))
    )


_DISPLAY_HEAD_RE = re.compile(r"\s*(?:disp(?:lay)?|screen|shown|shows)\b", re.I)  # ("Disp.")


def _without_display_word(items: list[str]) -> list[str]:
    """A display column's cells that all start with the same word ("POP 3.5 oz", "POP 3.0 oz",
    "POP none"): that word names the setting on the display, the rest is the value."""
    firsts = {item.split()[0] for item in items if len(item.split()) >= 2}
    if len(firsts) != 1 or len(items) < 2 or any(len(item.split()) < 2 for item in items):
        return items
    first = firsts.pop()
    if not first.isalpha():
        return items
    return list(dict.fromkeys(item[len(first) :].strip() for item in items))


FRACTIONS = {"½": ".5", "¼": ".25", "¾": ".75"}


def _quantity_column(units: list[Unit], i: int) -> list[str]:
    """A table column of durations after unit ``i`` ("| `60` | 1 hour |"), as minutes; a cell
    saying there is none ("no hold", "off", "--") is 0. Empty unless most cells are durations."""
    from apbot.model.values import parse_quantity

    rows: list[tuple[str, ...]] = []
    k = i + 1
    if k < len(units) and units[k].cells and not units[k].header:
        k += 1
    while k < len(units) and units[k].cells and units[k].header:
        rows.append(units[k].cells)
        k += 1
    if len(rows) < 3:
        return []
    width = min(len(r) for r in rows)
    for column in range(width - 1, -1, -1):
        items: list[str] = []
        for row in rows:
            cell = row[column].strip(" *`").lower()
            for frac, dec in FRACTIONS.items():
                cell = re.sub(rf"(\d)\s*{frac}", rf"\g<1>{dec}", cell).replace(frac, "0" + dec)
            q = parse_quantity(re.sub(r"\(.*?\)", "", cell).strip())
            if q and q[1] == "time":
                items.append(f"{q[0] / 60:g} min")
            elif re.match(r"^(?:no\b|none|off\b|-+$|–|—)", cell):
                items.append("0 min")
            else:
                break
        else:
            if sum(i != "0 min" for i in items) >= 2:
                return _dedupe(items)
    return []


def _bullet_items(units: list[Unit], i: int, lead: int = 0) -> list[str]:
    """The terms of the bullets after unit ``i`` ("- AUTO — dries until…"); a bullet may run
    to more sentences, and ``lead`` sentences may stand between ``i`` and the first bullet."""
    items: list[str] = []
    k = i + 1
    while lead and k < len(units) and not units[k].bullet and k <= i + lead:
        k += 1
    gap = 0
    while k < len(units) and len(items) < 16:
        u = units[k]
        k += 1
        if not u.bullet:
            if not items or u.heading != units[i].heading or gap >= 3 or u.cells:
                break
            gap += 1  # another sentence of the same bullet
            continue
        gap = 0
        m = re.match(r"^([A-Z0-9][A-Za-z0-9 +/&'-]{0,22}?)\s*(?::|—|–|-|=)\s", u.text)
        if not m:
            break
        items.append(m.group(1).strip())
    return items if len(items) >= 2 else []


def _dedupe(items: list[str]) -> list[str]:
    out: list[str] = []
    for item in items:
        if item not in out:
            out.append(item)
    return out
