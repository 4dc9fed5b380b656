"""Programme-dependent settings from tables: one row per programme, one column per setting.

Manuals give what a setting allows in each programme as a table ("| Program | Temperature |
Spin |", "| Menu | Texture options |"). A table whose first column names values of an already
read programme variable, and whose other column names another variable, turns that variable
into a dependent one with a case per row; a row that says nothing usable ("—", "fixed",
"automatic") leaves the setting out of that programme, as the manual implies.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_amounts import (
    _as_number,
    _finer_times,
    _header_unit,
    _no_toggle,
    _presets,
    _ranges_column,
)
from apbot.read.cases_cells import (
    _STEP_HEAD_RE,
    _cases,
    _defaults,
    _row_steps,
    defaults_head,
)
from apbot.read.cases_lists import as_choices, listed_cases, listed_column
from apbot.read.cases_marks import _mark, mark_cases
from apbot.read.cases_tables import _parent_values, _tables, advice_table, unnumbered
from apbot.read.goal_vocab import stem
from apbot.read.labels import words
from apbot.read.marks_legend import chart_legend, read_mark
from apbot.read.noun_columns import numbered_choice
from apbot.read.shapes import CHOICE_WORDS
from apbot.read.text import Unit

GENERIC = {
    "options", "option", "range", "ranges", "setting", "settings", "available", "values",
    "suggested", "default", "standard", "possible", "adjustable", "choices", "max", "min",
}  # fmt: skip
ADVICE_WORDS = {"suggested", "recommended", "typical", "advised", "usual"}  # not limits


def _matches(header: str, name: str, spec: dict[str, Any]) -> bool:
    hw = [w for w in words(header) if w not in GENERIC]
    if not hw:
        return False
    vw = set(words(name.replace("_", " "))) | set(words(str(spec.get("label", ""))))
    if any(
        h == v
        or (min(len(h), len(v)) >= 4 and (h.startswith(v) or v.startswith(h)))
        or stem(h) == stem(v)  # "Drying time" over DRY's own time
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
    for header, table in _tables(b.manual.units):
        if len(table) < 2 or advice_table(b.manual.units, table):
            continue
        header, rows = unnumbered(header, table)
        guessed_only = False  # only keys read with no values take a column-per-key chart's
        keyed = [  # a key heading a column of marks ("RINSE+" over "● / –") lists no values
            c
            for c, h in enumerate(header)
            if h.strip(" *.").upper() in keys and not _marks_column(rows, c)
        ]
        if len(keyed) >= 2:  # lists ("Cold, Warm")
            if not _guessed_listed(b, header, rows):
                continue  # a column per key ("| TEMP. | SPIN | SOIL |"): each lists its own values
            guessed_only = True
        parent, best = None, (1, False)
        for name, spec in b.variables.items():
            if spec.get("type") != "discrete" or spec.get("depends_on") or len(spec["values"]) < 3:
                continue
            if name in fixed or name in children:
                continue
            if numbered_choice(spec["values"]) and not _matches(header[0], name, spec):
                continue  # ("| Code | Hz |" over 0, 1, 2 …: not the levels VOX steps)
            hits = sum(bool(_parent_values(r.cells[0], spec["values"])) for r in rows)
            score = (hits, bool(set(words(name.replace("_", " "))) & CHOICE_WORDS))
            if hits >= 2 and score > best:
                parent, best = name, score
        if parent is None:
            continue
        pvalues = b.variables[parent]["values"]
        marked = mark_cases(b, header, rows, parent, fixed | parents | children)
        if marked:  # "WHITE | ◎ | ● | –" under "Menu | REGULAR | SOFTER | HARDER"
            parents.add(parent)
            children.add(marked)
            _no_toggle(b, marked, b.variables[marked]["cases"])
            continue
        header = _named_ranges(header, rows)
        lone = _lone_amount(b.variables, fixed | parents | {parent})
        if lone and (
            _names_another(table[0].heading, b.variables, {parent, lone})
            or not _every_choice(rows, b.variables[parent]["values"])
            or not _matches(header[0], parent, b.variables[parent])  # keyed by the choice itself
        ):
            lone = None  # "6.3 Target" over a Range column: the target's, not the lone amount's
        pressure = _pressure_unit(rows) if lone and any(map(_bare_range, header)) else ""
        if pressure:  # "CAR | 20 - 50 psi | 1 psi | 35 psi": the lone amount is a pressure
            rows = [replace(r, cells=tuple(_PRESSURE_RE.sub("", c) for c in r.cells)) for r in rows]
        for column in range(1, len(header)):
            cells = [r.cells[column] if column < len(r.cells) else "" for r in rows]
            if defaults_head(header[column], cells) or set(words(header[column])) & ADVICE_WORDS:
                continue
            both = {"range", "ranges"} & set(words(header[column])) and _ranges_column(rows, column)
            if _STEP_HEAD_RE.search(header[column]) and not both:
                continue  # "Time step": each row's step (read by _row_steps), not its values
                # ("Ripening time (range, step)" over "0:30 – 1:30, 15 min": both)
            head = [w for w in words(header[column]) if w not in GENERIC][:1]
            ranged = _ranges_column(rows, column)
            named = sorted(  # "Wash (min)": the variable named wash before any other "min" one
                b.variables.items(),
                key=lambda item: (
                    ranged and _switch(item[1]),  # a column of ranges: an amount before a switch
                    # "Design size range" over "70 - 100 %": the setting in % before DESIGN
                    not _unit_in_cells(str(item[1].get("unit", "")), cells),
                    not set(head) & set(words(item[0])),
                ),
            )
            for name, spec in named:
                if name == parent or name in fixed | parents or spec.get("depends_on"):
                    continue
                if not (
                    _matches(header[column], name, spec)
                    or (name == lone and ranged and _bare_range(header[column]))
                ):
                    continue  # (a bare "Range" column of ranges: the one amount there is)
                if spec.get("type") == "discrete" and _ranges_column(rows, column):
                    _as_number(b, name, spec, rows, column)  # the table says it is an amount
                elif _finer_times(spec, rows, column):
                    _as_number(b, name, spec, rows, column)  # "1 – 60 min" under "up to 12 h"
                guessed = name in b.unread and spec.get("type") == "numeric"
                if guessed_only and not guessed:
                    break
                if guessed and listed_column(rows, column):
                    cases = listed_cases(rows, column, pvalues)  # "Cold, Warm ▣, Hot"
                    if guessed and len(cases) >= 2:
                        as_choices(spec, cases)
                        b.unread.discard(name)
                elif _switch(spec):
                    cases = _cases(spec, _marks_told(b, rows, column), column, pvalues)
                else:
                    cases = _cases(spec, rows, column, pvalues)
                if len(cases) >= 2 and _presets(b, parent, name, cases, table[0]):
                    break
                if len(cases) >= 2:
                    if all("initial" in c for c in cases.values()) and spec.get("values"):
                        said = _dashed(rows, column, pvalues)  # "–": the setting is not offered
                        for value in pvalues:  # defaults per programme: the others keep all
                            if value not in said:
                                cases.setdefault(value, {"values": list(spec["values"])})
                    _row_steps(spec, cases, header, rows, column, pvalues)
                    _defaults(spec, cases, header, rows, column, pvalues)
                    for key in ("values", "ranges", "initial"):
                        spec.pop(key, None)
                    spec["depends_on"] = parent
                    spec["cases"] = cases
                    _header_unit(spec, header[column])
                    if pressure and name == lone:
                        spec["unit"] = pressure
                    parents.add(parent)
                    children.add(name)
                    _no_toggle(b, name, cases)
                    b.note(
                        f"variables.{name}.cases",
                        f"depends on {parent}: {len(cases)} cases",
                        b.manual.units.index(table[0]),
                    )
                break


def _bare_range(header: str) -> bool:
    """A column head that says only "Range" ("Setting range", "Range"): no setting's name."""
    hw = words(header)
    return bool(hw) and bool({"range", "ranges"} & set(hw)) and set(hw) <= GENERIC


# a pressure after a figure: a rating in most manuals (a pump's "15 bar"), which a table of
# per-choice ranges shows to be the setting's unit instead
_PRESSURE_RE = re.compile(r"(?<=\d)\s*(psi|bar|kPa)(?![\w])")


def _pressure_unit(rows: list[Unit]) -> str:
    """The one pressure unit the rows' cells give their figures in ("20 - 50 psi"), or ""."""
    found = {m.group(1) for r in rows for c in r.cells for m in _PRESSURE_RE.finditer(c)}
    return found.pop() if len(found) == 1 else ""


def _every_choice(rows: list[Unit], pvalues: list[str]) -> bool:
    """Whether the rows give three or more choices, nearly every one the parent has (a chart
    of all the presets, not of two programmes among many)."""
    named = {v for r in rows for v in _parent_values(r.cells[0], pvalues)}
    return len(named) >= 3 and len(named) >= 0.8 * len(pvalues)


def _names_another(heading: str, variables: dict[str, dict[str, Any]], own: set[str]) -> bool:
    """Whether a heading names a setting other than those in ``own``."""
    hw = {w[:5] for w in words(heading) if len(w) >= 4}
    return any(
        {w[:5] for w in words(name.replace("_", " ")) if len(w) >= 4} & hw
        for name in variables
        if name not in own
    )


def _lone_amount(variables: dict[str, dict[str, Any]], skip: set[str]) -> str | None:
    """The only numeric setting of the appliance (none per programme yet), or None."""
    amounts = [
        n
        for n, spec in variables.items()
        if n not in skip and spec.get("type") == "numeric" and not spec.get("depends_on")
    ]
    return amounts[0] if len(amounts) == 1 else None


def _unit_in_cells(unit: str, cells: list[str]) -> bool:
    """Whether every figure cell of a column (two or more) carries the setting's unit."""
    figures = [c for c in cells if re.search(r"\d", c)]
    if not unit or len(figures) < 2:
        return False
    after = re.compile(rf"\d\s*{re.escape(unit)}(?![A-Za-z])")
    return all(after.search(c) for c in figures)


def _switch(spec: dict[str, Any]) -> bool:
    """An on/off setting ("Low-heat drying on / off" held on DRY): a column of times under
    "Drying time" is DRY's own amount, not this switch's, where both answer to the word."""
    return sorted(spec.get("values") or []) == ["off", "on"]


def _marks_column(rows: list[Unit], column: int) -> bool:
    """Whether every row has a mark or a dash in the column ("●", "–", "✓"), one with a mark."""
    cells = [r.cells[column] if column < len(r.cells) else "" for r in rows]
    return all(_mark(c) is not None for c in cells) and any(_mark(c) for c in cells)


def _marks_told(b: Builder, rows: list[Unit], column: int) -> list[Unit]:
    """The rows with an on/off option's column of marks told in the words of the chart's
    legend ("●" → "on" where "● = starts ON", "✗" → "no" where "✗ = not available")."""
    lines = [r.line - 1 for r in rows]
    meanings = chart_legend(b.manual.lines, min(lines), max(lines))
    out = []
    for row in rows:
        if column < len(row.cells):
            cells = list(row.cells)
            cells[column] = read_mark(cells[column], meanings)
            row = replace(row, cells=tuple(cells))
        out.append(row)
    return out


_YES_NO = {"yes", "no", "y", "n", "—", "-", "–", ""}


def _dashed(rows: list[Unit], column: int, pvalues: list[str]) -> set[str]:
    """The programmes whose row in the chart has only a dash in this column: a programme
    that does not offer the setting, which the other programmes' defaults do not fill."""
    out: set[str] = set()
    for row in rows:
        if column < len(row.cells) and re.fullmatch(
            r"\s*[–—-]+\s*(?:\(.*\))?\s*", row.cells[column]
        ):
            out.update(_parent_values(row.cells[0], pvalues))
    return out


def _guessed_listed(b: Builder, header: tuple[str, ...], rows: list[Unit]) -> bool:
    """Whether a column lists choices ("Cold, Warm, Hot") for a key read with none."""
    return any(
        listed_column(rows, column) and _matches(header[column], name, spec)
        for column in range(1, len(header))
        for name, spec in b.variables.items()
        if name in b.unread and spec.get("type") == "numeric"
    )


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
