"""A table of what a key offers at each position of a dial ("| Position | SELECT steps |" with
"| TEMP | °C > °F |"; "Manual ranges per position:" over "| V~ | 6 V  60 V  600 V |").

Instruments whose dial picks a function (a meter, a charger, a generator) give, position by
position, the choices a second key steps through there. Such a table's first column names the
dial's positions and its other column lists the key's values for each: the key's setting
depends on the dial, a case per row; a row that lists fewer than two values ("automatic only",
"one range only") leaves the key out at that position. The key is named by the table's header
or by the sentence that introduces the table. A box table drawn without a rule under a header
has its first row read as the header; when that row's first cell names a position too, it is a
row. Run before ``apply_cases``: the key read with the positions themselves as its values (from
the table's first column) is the setting this table describes, not a parent to others.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.cases_tables import _norm, _tables
from apbot.read.labels import words
from apbot.read.text import Unit
from apbot.read.value_lists import find_list
from apbot.read.values import NUM

_AMOUNT = re.compile(rf"{NUM}\s*[^\W\d_]{{1,3}}", re.IGNORECASE)  # "6 V", "600 mV", "6 kΩ"


def _position(cell: str, values: list[str]) -> list[str]:
    """The dial positions a first cell names: each part exactly, or the one position whose
    printed sign it begins ("Ω" for "ω·)))▶|")."""
    out = []
    for part in re.split(r"\s*,\s*", _norm(cell)):
        if part in values:
            out.append(part)
            continue
        led = [v for v in values if part and v.startswith(part) and not v[len(part)].isalnum()]
        if len(led) == 1:
            out.append(led[0])
    return out


def _signed(item: str) -> tuple[str, str] | None:
    """An item printed as a sign and its name ("Ω resistance", "·))) continuity"): both."""
    m = re.fullmatch(r"(\S{1,5})\s+([a-z]{3,}(?:\s[a-z]{3,})?)", item.strip())
    if (m and not m.group(1).isalpha()) or (m and not m.group(1).isascii()):
        return m.group(2), m.group(1)
    return None


def _listed(cell: str) -> tuple[list[str], dict[str, str]]:
    """The values a row's cell lists, and the signs the display shows for named ones."""
    pairs = [_signed(p) for p in re.split(r"\s+(?:>|→)\s+", cell) if p.strip()]
    if len(pairs) >= 2 and all(pairs):  # "Ω resistance > ·))) continuity > ▶| diode"
        return [p[0] for p in pairs if p], {p[0]: p[1] for p in pairs if p}
    found = find_list(cell)
    if found and found[1] == "arrows" and len(found[0]) >= 2:  # "°C > °F": shown as printed
        return [v.lower() for v in found[0]], {v.lower(): v for v in found[0]}
    amounts = re.split(r"\s{2,}", cell.strip())
    if len(amounts) >= 2 and all(_AMOUNT.fullmatch(a) for a in amounts):
        return amounts, {}  # (as printed: "6 MΩ" is not "6 mΩ")
    return [], {}


def _dials(b: Builder) -> list[str]:
    turned = {i.name for i in b.infos if i.skill.startswith("turn")}
    return [
        f["variable"]
        for steps in b.features.values()
        for f in steps
        if set(f.get("actions", [])) & turned and f.get("variable") in b.variables
    ]


def _key_setting(b: Builder, names: str, parent: str) -> str | None:
    """The discrete setting (not the dial's) whose key the words name ("SELECT steps",
    "Manual ranges per position"): its label or its name."""
    said = {w.rstrip("s") for w in words(names) if len(w) >= 4}
    for name, spec in b.variables.items():
        if name == parent or spec.get("type") != "discrete" or spec.get("depends_on"):
            continue
        if name.endswith("_hold"):
            continue
        own = {w.rstrip("s") for w in words(name.replace("_", " ")) + words(spec.get("label", ""))}
        if said & own:
            return name
    return None


def position_cases(b: Builder) -> None:
    """Make a key's setting depend on the dial where a table lists its values per position."""
    for parent in dict.fromkeys(_dials(b)):
        values = [str(v) for v in b.variables[parent].get("values") or []]
        if len(values) < 4:
            continue
        for header, table in _tables(b.manual.units):
            rows: list[tuple[str, ...]] = [r.cells for r in table if len(r.cells) >= 2]
            if len(header) >= 2 and _position(header[0], values):
                rows.insert(0, header)  # a box with no header rule: its first row is a row
                head = ""
            else:
                head = " ".join(header[1:])
            named = [(r, _position(r[0], values)) for r in rows]
            if sum(bool(p) for _, p in named) < 3 or len(header) != 2:
                continue
            at = b.manual.units.index(table[0])
            intro = _intro(b.manual.units, at)
            child = _key_setting(b, f"{head} {intro}", parent)
            if child is None:
                continue
            cases: dict[str, Any] = {}
            shows: dict[str, str] = {}
            for row, positions in named:
                listed, signs = _listed(row[1])
                if len(listed) >= 2:
                    for position in positions:
                        cases[position] = {"values": listed}
                    shows.update(signs)
            if len(cases) < 2:
                continue
            spec = b.variables[child]
            back = _returned_to(b, str(spec.get("label", "")), cases)
            if back:  # "the next press returns to AUTO": the key's cycle starts there
                for case in cases.values():
                    case["values"] = [back, *case["values"]]
                _held_back(b, child, spec, back)
            for key in ("values", "ranges", "initial"):
                spec.pop(key, None)
            spec["depends_on"] = parent
            spec["cases"] = cases
            if shows:
                spec["show"] = shows
            b.note(f"variables.{child}.cases", f"per {parent} position: {len(cases)} cases", at)
            said = _display_said(b, spec, cases)
            if said is not None:  # "(g) what SELECT has chosen: °C or °F on TEMP; DC or AC …"
                b.indicators.append(child)
                b.note(f"display.indicators.{child}", "the display shows its choice", said)


_SHOWN_WORD = re.compile(r"\b(?:shows?|shown|chosen|appears?|displays?)\b", re.IGNORECASE)


def _display_said(b: Builder, spec: dict[str, Any], cases: dict[str, Any]) -> int | None:
    """The line that says the display shows the key's choice: it names the key, says what is
    shown or chosen, and prints two or more of its values; None when no line does."""
    label = str(spec.get("label", ""))
    listed = {str(v).lower() for case in cases.values() for v in case["values"]}
    if not label:
        return None
    for i, unit in enumerate(b.manual.units):
        text = unit.text
        if label not in text or not _SHOWN_WORD.search(text):
            continue
        printed = {p.lower() for p in re.split(r"[\s,;:()]+", text) if p}
        if len(listed & printed) >= 2:
            return i
    return None


_RETURNS_RE = re.compile(r"\breturns?\s+to\s+([A-Z]{2,8})\b")


def _returned_to(b: Builder, label: str, cases: dict[str, Any]) -> str:
    """The word in capitals a sentence naming the key says it returns to ("RANGE  steps
    through the ranges; hold 2 seconds to return to AUTO"), when it is
    none of the listed values and no key's name: the state before the first value, lower-cased;
    "" when no sentence says so."""
    if not label:
        return ""
    keys = {lab.text.upper() for lab in b.labels.values() if lab.text}
    listed = {str(v).lower() for case in cases.values() for v in case["values"]}
    mentions = {m for lab in b.labels.values() if lab.text == label for m in lab.mentions}
    for i in sorted(mentions):  # (its own sentences: the next key's legend line is not)
        m = _RETURNS_RE.search(b.manual.units[i].text)
        if m and m.group(1) not in keys and m.group(1).lower() not in listed:
            return m.group(1).lower()
    return ""


def _held_back(b: Builder, child: str, spec: dict[str, Any], back: str) -> None:
    """The key's hold read as a copy of its setting (the same values, "RANGE_hold"), where the
    key returns to ``back`` ("hold 2 seconds to return to AUTO"): the hold sets the setting to
    ``back``; the copy goes."""
    twin = f"{child}_hold"
    if twin not in b.variables or b.variables[twin].get("values") != spec.get("values"):
        return
    for steps in b.features.values():
        for step in steps:
            if step.get("variable") == twin:
                step["variable"] = child
                step["effect"] = {"to": back}
    del b.variables[twin]
    b.indicators[:] = [v for v in b.indicators if v != twin]


def _intro(units: list[Unit], at: int) -> str:
    """The sentence ending in ":" right before the table (its introduction), or ""."""
    k = at - 1
    while k >= 0 and units[k].cells:
        k -= 1
    return units[k].text if k >= 0 and units[k].text.rstrip().endswith(":") else ""


_SHOWN_HEAD = re.compile(r"^(?:display|shown|screen|indication|symbol)s?\b", re.IGNORECASE)
_NUMBERED = re.compile(r"\d{1,2}[.)]?")
_POSITION_HEAD = re.compile(r"(?:dial\s+)?(?:pos(?:ition)?s?|no|number)\.?|#", re.IGNORECASE)


def position_shows(b: Builder) -> None:
    """What the display shows at each dial position, from a table that numbers the positions
    in the dial's order ("| Pos. | Display | Measures |", rows 1 … 8 after OFF; its first
    column headed as the position or its number, not "presses") and has a column
    headed as the display: the cell of each row is its position's word ("nF" for the ⊣⊢
    position, "Ω" for Ω·)))▶|). Only where the numbers run 1 … N over the N positions past
    the first (OFF) or over all N."""
    for parent in dict.fromkeys(_dials(b)):
        spec = b.variables[parent]
        values = [str(v) for v in spec.get("values") or []]
        if len(values) < 4 or spec.get("show"):
            continue
        for header, table in _tables(b.manual.units):
            column = next((c for c, h in enumerate(header) if _SHOWN_HEAD.match(h.strip())), None)
            if column is None or column == 0 or not _POSITION_HEAD.fullmatch(header[0].strip()):
                continue  # ("| DRYING presses | Display |": presses counted, no positions)
            rows = [r.cells for r in table if len(r.cells) > column]
            if not all(_NUMBERED.fullmatch(r[0].strip()) for r in rows):
                continue
            numbers = [int(re.sub(r"\D", "", r[0])) for r in rows]
            if numbers != list(range(1, len(rows) + 1)):
                continue
            if len(rows) == len(values) - 1:
                named = values[1:]
            elif len(rows) == len(values):
                named = values
            else:
                continue
            shows = {v: r[column].strip() for v, r in zip(named, rows, strict=True)}
            if not all(shows.values()) or all(v == w.lower() for v, w in shows.items()):
                continue  # (each word the position's own name: nothing to learn)
            spec["show"] = {
                **({values[0]: values[0].upper()} if len(named) < len(values) else {}),
                **shows,
            }
            at = b.manual.units.index(table[0])
            b.note(f"variables.{parent}.show", "each position's display word, by number", at)
            b.indicators.append(parent)  # (the table says what the display shows at each)
            break
