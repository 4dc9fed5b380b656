"""A menu key that walks coded fields listed in a chart, each set with the stepping pair.

Small displays show the field being set by a short code in front of its value ("rA AUTO",
"EP 2", "F3 40"), and the manual lists the fields in a chart of codes, names and values:
"| Code | Setting | Values | … | rA | Ramp time | OFF, AUTO, 5, 10 … 45 |". A press of MENU
shows the first code, ▲ / ▼ change its value, the next press of MENU moves to the next code.
Read key by key, the chart's codes became the values of one setting of MENU ("ramp time,
pressure relief, mask type") and the fields were lost; here each row with a list of values
becomes a field of a walk the key opens and moves through, set with the pair.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_tables import _norm, _tables
from apbot.read.held_guesses import drop_unused
from apbot.read.menu_cells import CODE_HEAD, drawn_choice
from apbot.read.text import Unit
from apbot.read.walk_apply import apply_walk
from apbot.read.walk_ends import CLOSES_RE, pause_seconds
from apbot.read.walk_keys import pair_of, stepping_pairs

# a cell listing a field's values: two or more items split by commas or slashes
_ITEMS_RE = re.compile(r"\s*(?:,|/|;)\s*")
# the pair named by its arrows: "Press ▲ or ▼ until the value you want is shown"
_ARROWS_RE = re.compile(r"\bpress\s+[▲△↑]\s*(?:or|and|/)\s*[▼▽↓]", re.I)


def read_code_walks(b: Builder) -> None:
    """Replace a key's setting of chart codes (or the one setting its press then the pair was
    read to set) by the walk through the chart's fields."""
    pairs = stepping_pairs(b)
    if not pairs:
        return
    for fname, steps in list(b.features.items()):
        key = steps[0].get("actions") or []
        if len(key) != 1 or not 1 <= len(steps) <= 2:
            continue
        if len(steps) == 1:  # MENU steps through the codes: "rA → EP → MASK"
            spec = b.variables.get(str(steps[0].get("variable")), {})
            shows = spec.get("show") or {}
            if steps[0].get("effect") != "next" or spec.get("type") != "discrete":
                continue
            codes: list[str] | None = [str(c) for c in shows.values()]
            if len(shows) < 2 or not any(re.search(r"[A-Za-z0-9]", str(c)) for c in shows.values()):
                continue  # (icons, "♪ ≋ ϟ", show the values themselves: no fields' codes)
        elif "variable" in steps[0] or not isinstance(steps[1].get("effect"), dict):
            continue
        else:  # SET opens one setting the pair sets: the chart's codes, headed as codes
            codes = None
        walk = _chart_walk(b, key[0], codes, pairs)
        if walk is None:
            continue
        del b.features[fname]
        for step in steps:
            drop_unused(b, str(step.get("variable")))
        apply_walk(b, key[0], key[0], walk, named=False)


def _chart_walk(
    b: Builder, key: str, codes: list[str] | None, pairs: list[tuple[list[str], list[str]]]
) -> dict[str, Any] | None:
    """The walk a chart of the key's codes lays out: each code's row with a list of values is
    a field; the chart's section names the key and the pair (its steps say how to walk).
    Without the key's codes read, the chart's column must be headed as the codes ("Code")."""
    label = _label(b, key)
    wanted = {c.lower() for c in codes or ()}
    for header, rows in _tables(b.manual.units):
        for column in range(min(len(r.cells) for r in rows)):
            cells = {_norm(r.cells[column]) for r in rows}
            if codes is None:
                if column >= len(header) or not CODE_HEAD.match(header[column]):
                    continue
                wanted = {c for c in cells if c}
            if not wanted or not wanted <= cells:
                continue
            fields = _fields(rows, column, wanted)
            if fields is None:
                continue
            at = b.manual.units.index(rows[0])
            section = _section(b.manual.units, at)
            said = " ".join(u.text for u in section if not u.cells)
            pair = next((p for u in section if (p := pair_of(b, pairs, u.text))), None)
            if pair is None and len(pairs) == 1 and any(_ARROWS_RE.search(u.text) for u in section):
                pair = pairs[0]  # "Press ▲ or ▼" where the keys' labels were read otherwise
            if (
                pair is None
                or label is None
                or not re.search(rf"(?<!\w){re.escape(label)}(?!\w)", said)
            ):
                return None
            timeout = next(
                (s for u in section if CLOSES_RE.search(u.text) and (s := pause_seconds(u.text))),
                None,
            )
            return {"pair": pair, "fields": fields, "at": at, "timeout": timeout, "said": said}
    return None


def _fields(rows: list[Unit], column: int, codes: set[str]) -> list[dict[str, Any]] | None:
    """Each coded row's field: its name (the next cell), its values (the first later cell
    listing two or more), each shown after the code as the display prints it."""
    fields: list[dict[str, Any]] = []
    for row in rows:
        cells = row.cells
        code = cells[column].strip().strip("*`")
        if _norm(code) not in codes or column + 2 >= len(cells):
            continue
        name = _norm(cells[column + 1])
        listed = next((c for c in cells[column + 2 :] if len(_items(c)) >= 2), None)
        if not name or listed is None:
            return None
        values, show = [], {}
        for item in _items(listed):
            drawn = drawn_choice(item)  # "▽ full face": the name, shown as the symbol
            value = _norm(drawn[1] if drawn else item)
            values.append(value)
            show[value] = f"{code} {drawn[0] if drawn else item}"
        field_name = "_".join(re.findall(r"[a-z0-9]+", name)[:3])
        fields.append({"name": field_name, "label": code, "values": values, "show": show})
    return fields if len(fields) >= 2 else None


def _section(units: list[Unit], at: int) -> list[Unit]:
    """The chart's section, before it and after it, and the one sub-section after it ("Using
    the menu"): where the manual says how the key and the pair walk the chart."""
    start = at
    while start > 0 and units[start - 1].heading == units[at].heading:
        start -= 1
    headings = [units[at].heading]
    out = units[start:at]
    for unit in units[at : at + 40]:
        if unit.heading not in headings:
            if len(headings) == 2:
                break
            headings.append(unit.heading)
        out.append(unit)
    return out


def _items(cell: str) -> list[str]:
    """The values a cell lists ("OFF, AUTO, 5, 10"), its remark in brackets left out."""
    bare = re.sub(r"\([^)]*\)", " ", cell).strip()
    return [i for i in _ITEMS_RE.split(bare) if i and len(i) <= 24]


def _label(b: Builder, action: str) -> str | None:
    """The printed name of the one control an action works: the chart's section names the key."""
    controls = next((i.controls for i in b.infos if i.name == action), ())
    return b.labels[controls[0]].text if len(controls) == 1 and controls[0] in b.labels else None
