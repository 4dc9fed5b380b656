"""Settings reached through a numbered menu: "hold SET for 3 s; the display shows F1 …".

Many panels have no key per setting. A held key opens a settings menu whose items carry codes
(F1 … F5, P1 … P3, d1 … d4), the stepping pair changes the item shown, and a press of the
same key moves on to the next item (after the last one it leaves the menu). Read key by key,
the held key looks like a toggle of its own, the short press like an amount of its own, and
the pair like one more amount, so no item can be set. This rule reads the menu as one
feature whose steps follow the manual's procedure: enter, pair on the first item, next key,
pair on the second item, …, next key (the model format's sequential steps; the
"SET/TIME then ▲/▼" switch of ``roles_shared`` is written the same way).

What marks a menu (structural, whatever the appliance): a family of codes of one prefix
numbered from 1 (or 0) without gaps, each led by its own line or table row that names a
setting ("F3  Humidity target", "| P2 | automatic close | -- · 1 · 2 · 5 · 10 min |"); a
sentence tying the codes to a menu, programming or settings mode; and the key that opens it,
from the step that opens it ("Hold PROG for 3 seconds. The display shows P1 …") or from its
own legend ("| SET | … | 3 s: open the setting menu |"). Each item's values come from its own
row or the lines under its heading. The display shows the code with the value, so each
item's label is its code.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from apbot.model.values import format_hms, parse_hms
from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import numeric_list
from apbot.read.roles_lists import list_evidence
from apbot.read.shapes import Evidence
from apbot.read.value_lists import bare_list, find_list
from apbot.read.values import Range, find_initial, find_ranges, find_step, seconds, unit_name

_CODE = r"(?P<pre>[A-Za-z]{1,2})-?(?P<num>\d{1,2})"
_CODE_RE = re.compile(rf"^{_CODE}$")
_LEAD_RE = re.compile(rf"^\s*{_CODE}\b\s*[:.=–-]?\s+(?P<rest>[A-Za-z][^|]*)$")
_MENU_RE = re.compile(
    r"\b(?:menu|programming|program(?:me)?\s+mode|settings?\s+mode|set-?up\s+mode|"
    r"parameters?|settings|set-?up|options|functions?\s+codes?)\b",
    re.IGNORECASE,
)
_SHOWS_RE = re.compile(r"\b(?:shows?|appears?|displays?|reads?|flash(?:es)?)\b", re.IGNORECASE)
_HOLD_CLAUSE = re.compile(r"\b(?:hold\w*|\d+\s*s(?:ec\w*)?)\b[^.;|]*", re.IGNORECASE)
_NEXT_RE = re.compile(r"\bnext\s+(?:item|parameter|setting|function|code|menu\s+item|step)\b", re.I)
_DEFAULT_HEAD = re.compile(r"\b(?:factory|default|standard|preset|initial)\b", re.IGNORECASE)
_VALUES_HEAD = re.compile(r"\b(?:values?|range|settings?|options?|choices?)\b", re.IGNORECASE)
_OFF_MARK = re.compile(r"^(?:--+|-|off|oFF|OFF)(?:\s*\((?:off|none)\))?$", re.IGNORECASE)
_ELLIPSIS = re.compile(r"\s*(?:…|\.\.\.)\s*")
_PART_SPLIT = re.compile(r"\s+[-–]\s+|\s*[·•,;/]\s*")
_NUM_PART = re.compile(r"^([-−]?\d+(?:[.,]\d+)?)\s*([^\d\s].{0,8})?$")
_SPELLED = r"\b{v}\s*\(\s*([A-Za-z][a-z]+)\s*\)"  # "C (Celsius)": the value's full name


@dataclass
class MenuItem:
    """One item of the menu: its code, the setting it names, and the units about it."""

    code: str
    name: str
    at: int
    texts: list[tuple[int, str]] = field(default_factory=list)  # (unit, text about its values)
    initial: str | None = None


def _name_of(rest: str) -> str:
    """The setting a lead line names: its words up to a new sentence or a value ("Light time
    How long …" → "Light time"; "Incubation temperature" stays)."""
    out: list[str] = []
    for k, w in enumerate(rest.split()):
        if k and ((w[:1].isupper() and not w.isupper()) or re.match(r"[\d(.\-–]", w)):
            break
        if k >= 5:
            break
        out.append(w)
    return " ".join(out).strip(" .:,")


def _row_item(unit: Any) -> tuple[str, str, int, int] | None:
    """(prefix, name, number, code cell) of a table row led by a code ("| P1 | light time … |")."""
    for k, cell in enumerate(unit.cells[:2]):
        m = _CODE_RE.match(cell.strip())
        if m and k + 1 < len(unit.cells) and re.match(r"[A-Za-z]", unit.cells[k + 1].strip()):
            return m.group("pre"), unit.cells[k + 1].strip(), int(m.group("num")), k
    return None


def find_items(b: Builder) -> list[MenuItem]:
    """The menu's items in order, or [] when the manual has no numbered settings menu."""
    units = b.manual.units
    found: dict[str, dict[int, MenuItem]] = {}
    for i, unit in enumerate(units):
        if unit.cells:
            row = _row_item(unit)
            if row is None:
                continue
            pre, name, num, k = row
            code = unit.cells[k].strip()
            item = found.setdefault(pre, {}).setdefault(num, MenuItem(code, name, i))
            cells = unit.cells[k + 2 :]
            heads = unit.header[k + 2 :] if unit.header else ()
            for c, cell in enumerate(cells):
                head = heads[c] if c < len(heads) else ""
                if _DEFAULT_HEAD.search(head):
                    item.initial = cell.strip()
                elif not head or _VALUES_HEAD.search(head) or c == 0:
                    item.texts.append((i, cell))
            if len(name.split()) < len(item.name.split()):
                item.name = name
            continue
        m = _LEAD_RE.match(unit.text)
        if m is None:
            continue
        rest = m.group("rest")
        if re.search(rf"\b{re.escape(m.group('pre'))}-?\d", rest):
            continue  # "F1 unit C F2 temperature …": a list of several items, not one's lead
        name = _name_of(rest)
        if not name or len(words(name)) == 0:
            continue
        pre, num = m.group("pre"), int(m.group("num"))
        code = unit.text.strip().split()[0].rstrip(":.=")
        item = found.setdefault(pre, {}).setdefault(num, MenuItem(code, name, i))
        if len(name.split()) < len(item.name.split()) or (item.at != i and not item.texts):
            item.name = name
        item.texts += _body(b, i, pre, rest[len(name) :])
    for pre, items in found.items():
        nums = sorted(items)
        if len(nums) < 2 or nums[0] not in (0, 1) or nums != list(range(nums[0], nums[-1] + 1)):
            continue
        if not _tied_to_menu(b, pre, items[nums[0]].at):
            continue
        return [items[n] for n in nums]
    return []


def _body(b: Builder, i: int, pre: str, tail: str) -> list[tuple[int, str]]:
    """The text under an item's own lead line, up to the next item or heading (at most 6 units)."""
    units = b.manual.units
    out = [(i, tail)] if tail.strip() else []
    for j in range(i + 1, min(i + 7, len(units))):
        text = units[j].text
        if _LEAD_RE.match(text) or units[j].heading != units[i].heading:
            break
        out.append((j, text))
    return out


def _tied_to_menu(b: Builder, pre: str, first: int) -> bool:
    """A sentence or heading ties the codes to a settings menu ("THE SETTING MENU (F1 - F5)",
    "P1 … / P2 …  programming, parameter and value"), or the line that leads into the first
    item names one ("User settings:")."""
    lead = b.manual.units[first - 1].text if first else ""
    if lead.rstrip().endswith(":") and _MENU_RE.search(lead):
        return True
    code = re.compile(rf"\b{re.escape(pre)}-?[01]\b")
    return any(
        code.search(u.text) and _MENU_RE.search(u.text) for u in b.manual.units if not u.cells
    ) or any(code.search(u.heading) and _MENU_RE.search(u.heading) for u in b.manual.units)


def _label_at(b: Builder, token: str, text: str) -> bool:
    lab = b.labels.get(token)
    return bool(lab and lab.text and re.search(rf"(?<!\w){re.escape(lab.text)}(?!\w)", text))


def find_entry(b: Builder, keys: list[ActionInfo], first: str) -> ActionInfo | None:
    """The action that opens the menu: the held (or pressed) key of the step after which the
    display shows the first item ("Hold PROG for 3 seconds. The display shows P1 …"), else a
    hold whose own legend opens the menu ("| SET | … | 3 s: open the setting menu |")."""
    units = b.manual.units
    code = re.compile(rf"(?<!\w){re.escape(first)}(?!\w)")
    for i, unit in enumerate(units):
        if not (code.search(unit.text) and _SHOWS_RE.search(unit.text)):
            continue
        for j in (i, i - 1):
            if j < 0:
                continue
            text = units[j].text
            for skill in ("hold", "press"):
                verb = re.search(
                    r"\bhold\b|\bkeep\b.*\bpressed\b"
                    if skill == "hold"
                    else r"\b(?:press|touch|push|tap)\b",
                    text,
                    re.IGNORECASE,
                )
                if verb is None:
                    continue
                for key in keys:
                    if (
                        key.skill == skill
                        and len(key.controls) == 1
                        and _label_at(b, key.controls[0], text[verb.start() :])
                    ):
                        return key
    for key in keys:
        if key.skill != "hold" or len(key.controls) != 1:
            continue
        lab = b.labels.get(key.controls[0])
        for i in lab.mentions if lab else []:
            unit = units[i]
            told = " ".join(unit.cells) if unit.cells else unit.text
            if any(_MENU_RE.search(c.group(0)) for c in _HOLD_CLAUSE.finditer(told)):
                return (
                    key  # "| SET | … | 3 s: open the setting menu |", "Hold 3 seconds: programming"
                )
    return None


def _next_key(b: Builder, keys: list[ActionInfo], entry: ActionInfo) -> ActionInfo | None:
    """The key that moves to the next item: a press of the entry's own key (or the entry
    itself when it is a press), else a key whose sentence says it goes to the next item."""
    for key in keys:
        if key.skill == "press" and key.controls == entry.controls:
            return key
    for key in keys:
        lab = b.labels.get(key.controls[0]) if key.skill == "press" else None
        if lab and any(_NEXT_RE.search(b.manual.units[i].text) for i in lab.mentions):
            return key
    return None


def _parts(text: str) -> list[str] | None:
    """The values a printed run gives ("1 h - 2 h - 3 h - 4 h - 6 h", "-- (off) · 1 · 2 · 5 · 10
    min", "1 · 2 · 3 … 9"), numbers with their unit and "off", or None."""
    text = re.sub(r"\s*\((?:off|none)\)", "", text.strip().rstrip("."), flags=re.I)
    parts = [p.strip() for p in _PART_SPLIT.split(text) if p.strip()]
    if len(parts) < 3:
        return None
    out: list[str] = []
    unit = ""
    for p in parts:
        pieces = _ELLIPSIS.split(p)
        for k, piece in enumerate(pieces):
            if _OFF_MARK.match(piece):
                out.append("off")
                continue
            m = _NUM_PART.match(piece)
            if m is None or (
                m.group(2) and not unit_name(m.group(2).strip()) and m.group(2).strip()
            ):
                return None
            if k and len(out) >= 2:  # "3 … 9": the run's step fills the gap
                a, b2 = float(out[-2].split()[0]), float(out[-1].split()[0])
                step, hi = b2 - a, float(m.group(1).replace(",", "."))
                x = b2 + step
                while step > 0 and x < hi - 1e-9 and len(out) < 200:
                    out.append(f"{x:g}")
                    x += step
            out.append(m.group(1).replace(",", "."))
            if m.group(2):
                unit = m.group(2).strip()
    if sum(v != "off" for v in out) < 2:
        return None
    return [v if v == "off" or not unit else f"{v} {unit}" for v in out]


def _item_variable(b: Builder, item: MenuItem) -> str | None:
    """A variable for the item from what its own row or lines say (None: nothing usable)."""
    name = re.sub(r"\s*\(.*?\)", "", item.name).strip()
    ranges: list[Range] = []
    step: tuple[float, str] | None = None
    initial = next((f for _i, t in item.texts if (f := find_initial(t))), None)
    if (cases := _cases(b, item)) is not None:
        return cases
    for i, text in item.texts:
        if b.manual.units[i].cells and i != item.at:
            continue  # (a table under the item: its cases, read above)
        if ranges:  # (a range read first is the item's: no list after it, only its step)
            step = step or find_step(text)
            continue
        run = re.search(r"(?<![\w.])(?:--|\d)", text)  # "The setback runs 0 h - 2 h - …"
        parts = _parts(text) or (_parts(text[run.start() :]) if run else None)
        if parts:
            return _listed(b, item, name, parts)
        found = find_list(text)
        listed = found[0] if found else bare_list(text) or []
        aside = re.search(r"\(([^()]*[/·,][^()]*)\)", text)  # "F1: temperature unit (C/F)"
        if not listed and aside and i == item.at:
            listed = [p.strip() for p in re.split(r"\s*[/·,]\s*", aside.group(1)) if p.strip()]
        if len(listed) >= 2 and not numeric_list(listed):
            values = []
            for v in listed:
                full = re.search(_SPELLED.format(v=re.escape(v)), text)
                values.append(full.group(1).lower() if full else v)
            return b.add_discrete(name, values, item.code, None)
        if not ranges:
            ranges = find_ranges(text)
        if step is None:
            step = find_step(text)
    if not ranges:
        return None
    r = ranges[0]
    if step and (not step[1] or unit_name(step[1]) == r.unit or not r.unit):
        r = Range(r.low, r.high, r.unit or step[1], r.step or step[0])
    ev = Evidence(ranges=[r], range_at=item.at, step=step, step_at=item.at)
    var = b.add_number(name, item.code, ev, cyclic=False)
    _as_printed(b, var, r.unit)
    if initial is not None:
        _start(b, var, initial[0], r.unit, item.at)
    elif item.initial and (num := re.match(r"[-−]?\d+(?:\.\d+)?", item.initial)):
        _start(b, var, float(num.group(0)), r.unit, item.at)
    return var


def _as_printed(b: Builder, var: str, unit: str) -> None:
    """A duration the menu prints as a bare number ("P1 2.5" for 2.5 min) stays a number in
    its printed unit: read as a time it would be shown as 02:30, which the display never
    shows."""
    spec = b.variables[var]
    if spec["type"] != "time" or unit not in ("s", "min", "h"):
        return
    per = seconds(1, unit)
    spec["type"] = "numeric"
    spec["unit"] = unit
    spec.pop("format", None)
    spec["ranges"] = [
        [_tidy(parse_hms(lo) / per), _tidy(parse_hms(hi) / per), _tidy(st / per)]
        for lo, hi, st in spec["ranges"]
    ]
    if "initial" in spec:
        spec["initial"] = _tidy(parse_hms(spec["initial"]) / per)


def _start(b: Builder, var: str, value: float, unit: str, at: int) -> None:
    """Start ``var`` at ``value`` (in the unit its values were printed in) when it holds it."""
    spec = b.variables[var]
    if spec["type"] == "time":
        unit = unit if unit in ("s", "min", "h") else "min"
        start: Any = format_hms(seconds(value, unit))
        inside = any(
            parse_hms(lo) <= parse_hms(start) <= parse_hms(hi) for lo, hi, _ in spec["ranges"]
        )
    else:
        start = int(value) if float(value).is_integer() else value
        inside = any(lo <= value <= hi for lo, hi, _ in spec["ranges"])
    if inside:
        spec["initial"] = start
        b.note(f"variables.{var}.initial", f"starts at {start}", at)


_STEP_HEAD = re.compile(r"\b(?:step|one press|per press|increment)s?\b", re.IGNORECASE)


def _cases(b: Builder, item: MenuItem) -> str | None:
    """An item whose range depends on an earlier item, told as a table under it whose first
    column is headed by that item's code ("| unit (F1) | range | one press | default |", one
    row per unit): a setting with one case per value of the earlier item."""
    units = b.manual.units
    rows = [units[i] for i, _t in item.texts if units[i].cells and units[i].header and i != item.at]
    if not rows:
        return None
    head = rows[0].header
    parent = next(
        (
            v
            for v, spec in b.variables.items()
            if re.search(rf"\b{re.escape(str(spec.get('label')))}\b", head[0])
            and spec.get("type") == "discrete"
        ),
        None,
    )
    if parent is None:
        return None
    values = [str(v) for v in b.variables[parent]["values"]]
    cases: dict[str, Any] = {}
    for row in rows:
        key = row.cells[0].strip().lower()
        match = [v for v in values if v.lower() == key] or [
            v for v in values if v.lower().startswith(key)
        ]
        found = [r for c in row.cells[1:] for r in find_ranges(c)]
        if len(match) != 1 or not found:
            continue
        step, start = None, None
        for h, c in zip(head[1:], row.cells[1:], strict=False):
            num = re.fullmatch(r"\s*([-−]?\d+(?:\.\d+)?)\s*\S{0,3}\s*", c)
            if num and _STEP_HEAD.search(h):
                step = float(num.group(1))
            elif num and _DEFAULT_HEAD.search(h):
                start = float(num.group(1))
        r = found[0]
        st = r.step or step or 1.0
        case: dict[str, Any] = {"ranges": [[_tidy(r.low), _tidy(r.high), _tidy(st)]]}
        if start is not None and r.low <= start <= r.high:
            case["initial"] = _tidy(start)
        cases[match[0]] = case
    if not cases:
        return None
    name = b.unique(re.sub(r"\s*\(.*?\)", "", item.name).strip(), b.variables)
    b.variables[name] = {
        "type": "numeric",
        "depends_on": parent,
        "cases": cases,
        "label": item.code,
    }
    b.note(f"variables.{name}.cases", f"its range per {parent}", b.manual.units.index(rows[0]))
    return name


def _tidy(x: float) -> float | int:
    return int(x) if float(x).is_integer() else round(x, 6)


def _listed(b: Builder, item: MenuItem, name: str, parts: list[str]) -> str:
    """An item whose values are printed one by one: numbers (a piecewise range) or, with "off"
    among them, a list of names."""
    initial = None
    if item.initial:
        init = item.initial.strip()
        initial = next(
            (p for p in parts if p.split()[0] == init or (p == "off" and _OFF_MARK.match(init))),
            None,
        )
    if initial is None and (
        told := next((f for _i, t in item.texts if (f := find_initial(t))), None)
    ):
        initial = next((p for p in parts if p.split()[0] == f"{told[0]:g}"), None)
    if "off" not in parts and numeric_list(parts):
        var = b.add_number(name, item.code, list_evidence(Evidence(values=parts)), cyclic=False)
        unit = unit_name(parts[-1].split()[-1]) if " " in parts[-1] else ""
        _as_printed(b, var, unit)
        if initial is not None:
            _start(b, var, float(initial.split()[0]), unit, item.at)
        return var
    ev2 = Evidence(values=parts, values_at=item.at, initial=initial, initial_at=item.at)
    var = b.add_discrete(name, parts, item.code, ev2)
    b.variables[var]["wrap"] = False
    return var


def assign_menu(
    b: Builder, keys: list[ActionInfo], pairs: dict[str, dict[str, list[str]]]
) -> set[str]:
    """Read a numbered settings menu into one feature; returns the actions it took (and drops
    the stepping pair it uses from ``pairs``)."""
    items = find_items(b)
    if not items or not pairs:
        return set()
    entry = find_entry(b, keys, items[0].code)
    if entry is None:
        return set()
    nxt = _next_key(b, [k for k in keys if k.name != entry.name], entry) or (
        entry if entry.skill == "press" else None
    )
    if nxt is None:
        return set()
    by_name = {k.name: k for k in b.infos}
    base = "" if "" in pairs else next(iter(pairs))
    pair = pairs[base]
    ups = [a for a in pair["up"] if by_name[a].skill == "press"]
    downs = [a for a in pair["down"] if by_name[a].skill == "press"]
    if len(ups) != 1 or len(downs) != 1:
        return set()
    steps: list[dict[str, Any]] = [{"actions": [entry.name]}]
    made = 0
    for k, item in enumerate(items):
        if k:
            steps.append({"actions": [nxt.name]})
        var = _item_variable(b, item)
        if var is None:  # an item the manual gives no values for: passed with ▲ / ▼ all the same
            steps.append({"actions": [ups[0], downs[0]]})
            continue
        made += 1
        steps.append(
            {
                "actions": [ups[0], downs[0]],
                "variable": var,
                "effect": {ups[0]: "next", downs[0]: "prev"},
            }
        )
        b.note(f"variables.{var}", f"menu item {item.code}", item.at)
    if made == 0:
        return set()
    steps.append({"actions": [nxt.name]})
    b.feature("settings_menu", steps)
    b.note(
        "features.settings_menu", f"{entry.name} opens the menu, {nxt.name} goes on", items[0].at
    )
    del pairs[base]
    return {entry.name, nxt.name, ups[0], downs[0]}
