"""Function keys: a row of keys that each choose how the appliance works (MICRO, GRILL,
CONVECTION… or BAKE, ROAST, PIZZA…), each opening a procedure of its own that types values and
ends with START ("1. Press GRILL. 2. Enter the cooking time. 3. Press START.").

Manuals of ovens, microwaves and cookers say such keys are touched first ("Always touch the
function key first, then enter the values"). They are the values of one choice, each key going
to its own; the number keys after them enter what each procedure says (a cooking time all of
them share, a temperature or weight of their own), and a key pressed again to pick something
("Press COMBI repeatedly to select another combination") steps a setting of its own while
choosing its function. Read key by key, each would be an amount of its own typed on the keypad.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_common import label_of, mentions_of, plain
from apbot.read.roles_pads import CODE_RE
from apbot.read.text import Unit
from apbot.read.values import find_ranges

# the manual names the row as one kind of key ("touch the function key first")
GROUP_RE = re.compile(
    r"\b(function|mode|programme|program|cooking)\s+(?:keys?|buttons?|pads?|touch\s*pads?)\b",
    re.IGNORECASE,
)
_VERB = r"(?:press|touch|push|tap)(?:es|ed)?\s+(?:the\s+)?"
_STEP_NUMBER = re.compile(r"^\W*\d+[.)]?\W*$")  # a step's number left alone ("2.")
_ENTER_RE = re.compile(
    r"\b(?:enter|type|key in|input)\s+(?:the\s+|a\s+)?((?:[a-z]+\s+){0,2}?"
    r"(?:time|duration|temperature|temp|weight|quantity|amount|portions?|servings?))\b",
    re.IGNORECASE,
)
_PICK_RE = re.compile(r"\b(?:select|choose|pick|until|as often|step|cycle)", re.IGNORECASE)
_PICKED_NOUN = re.compile(
    r"\b(?:select|choose|pick)\w*\s+(?:a\s+|an\s+|the\s+)?(?:lower\s+|higher\s+|another\s+|other\s+)?"
    r"([a-z]+)",
    re.IGNORECASE,
)
_NUMBER_RUN = re.compile(r"\b(\d+(?:\s*/\s*\d+){2,})\s*(W|g|°C|°F|%)(?!\w)")
_TIME_WORDS = {"time", "duration"}
_WEIGHT_WORDS = {"weight", "quantity", "amount", "portion", "portions", "serving", "servings"}


@dataclass
class _Procedure:
    """What one key's numbered procedure does after its first press."""

    key: ActionInfo
    first: int  # the unit of "Press KEY"
    steps: list[tuple[str, int]] = field(default_factory=list)  # ("enter", i) / ("again", i)
    cycles: int | None = None  # a unit saying the key is pressed again to pick something


def function_keys(b: Builder, keys: list[ActionInfo]) -> tuple[str, list[_Procedure]] | None:
    """Three or more keys each starting a procedure of their own that types values and ends
    with START, in a manual naming them as one kind of key; with the kind's noun."""
    units = b.manual.units
    said = next((m for u in units if (m := _group_named(b, u.text))), None)
    starts = [label_of(b, i.token) for i in b.infos if "start" in words(i.token)]
    if said is None or not starts:
        return None
    found: list[_Procedure] = []
    for key in keys:
        if key.skill != "press" or key.controls[0] not in b.labels:
            continue
        proc = _procedure(b, key, starts)
        if proc is not None and any(kind == "enter" for kind, _ in proc.steps):
            found.append(proc)
    if len(found) < 3:
        return None
    noun = said.group(1).lower()
    return ("function" if noun == "cooking" else noun), found


def _group_named(b: Builder, text: str) -> re.Match[str] | None:
    """The kind named for the row ("touch the function key first"), not one key called so
    ("press the MODE button": a key labelled MODE names no row of keys)."""
    labels = {lab.text.strip(" .").casefold() for lab in b.labels.values() if lab.text}
    for m in GROUP_RE.finditer(text):
        if m.group(1).casefold() not in labels:
            return m
    return None


def _procedure(b: Builder, key: ActionInfo, starts: list[str]) -> _Procedure | None:
    """The key's own procedure: a unit led by pressing it, then the steps up to START."""
    units = b.manual.units
    label = re.escape(label_of(b, key.controls[0]))
    first_re = re.compile(rf"^\W*(?:\d+[.)]\s*)?{_VERB}{label}(?![\w/])", re.IGNORECASE)
    again_re = re.compile(rf"\b{_VERB}{label}\s+(?:again|repeatedly|once more)", re.IGNORECASE)
    start_re = re.compile(
        rf"^\W*(?:\d+[.)]\s*)?{_VERB}(?:{'|'.join(map(re.escape, starts))})(?![\w/])",
        re.IGNORECASE,
    )
    for i in mentions_of(b, key.controls[0]):
        if not first_re.match(units[i].text) or units[i].cells:
            continue
        proc = _Procedure(key, i)
        if again_re.search(units[i].text) or re.search(r"\brepeatedly\b", units[i].text, re.I):
            proc.cycles = i  # "Press AUTO COOK repeatedly until the number … appears"
        for k in range(i + 1, min(i + 14, len(units))):
            text = units[k].text
            if units[k].heading != units[i].heading:
                break
            if start_re.match(text):
                return proc
            if _STEP_NUMBER.match(text) or units[k].cells:
                continue
            if again_re.search(text):
                if _PICK_RE.search(text) and not re.search(r"\bconfirm", text, re.I):
                    proc.cycles = proc.cycles if proc.cycles is not None else k
                else:
                    proc.steps.append(("again", k))
            elif _ENTER_RE.search(text):
                proc.steps.append(("enter", k))
    return None


def assign_functions(
    b: Builder, noun: str, procs: list[_Procedure], digits: list[str]
) -> str | None:
    """One choice variable with a value per key; each key's feature goes to its value (or steps
    its own setting while choosing it) and then types what its procedure enters. Returns the
    shared time variable the number keys set, if any."""
    var = b.unique(noun, b.variables)
    values = [plain(label_of(b, p.key.controls[0])) for p in procs]
    b.variables[var] = {"type": "discrete", "values": values, "label": noun.upper()}
    b.note(
        f"variables.{var}",
        f"{noun} keys each start a procedure of their own: {', '.join(values)}",
        procs[0].first,
    )
    shared: dict[str, str] = {}
    for proc, value in zip(procs, values, strict=True):
        first = _first_step(b, proc, var, value)
        steps: list[dict[str, Any]] = [first]
        for kind, at in proc.steps:
            if kind == "again":
                steps.append({"actions": [proc.key.name]})
                continue
            if not digits:
                continue
            target = _entered(b, proc, at, shared)
            steps.append({"actions": list(digits), "variable": target})
        while steps and "variable" not in steps[-1]:
            steps.pop()  # a last press that confirms nothing typed after it
        b.feature(proc.key.token, steps)
        b.note(f"features.{proc.key.token}", f"{value}: its procedure's steps", proc.first)
    return shared.get("time")


def _first_step(b: Builder, proc: _Procedure, var: str, value: str) -> dict[str, Any]:
    """Going to the key's value, or stepping the setting it picks when pressed again."""
    go: dict[str, Any] = {"actions": [proc.key.name], "variable": var, "effect": {"to": value}}
    at = proc.cycles if proc.cycles is not None else _legend_cycles(b, proc.key)
    if at is None:
        return go
    own = _cycled(b, proc, at)
    if own is None:
        return go
    name, effect = own
    return {"actions": [proc.key.name], "variable": name, "effect": effect, "set": {var: value}}


def _legend_cycles(b: Builder, key: ActionInfo) -> int | None:
    """The key's legend row says it is pressed repeatedly ("| MICRO | Press repeatedly to choose
    the output. |")."""
    label = label_of(b, key.controls[0]).upper()
    for i in mentions_of(b, key.controls[0]):
        cells = b.manual.units[i].cells
        if (
            len(cells) >= 2
            and cells[0].strip(" *").upper() == label
            and re.search(r"\b(?:repeatedly|again|each press)\b", cells[1], re.I)
        ):
            return i
    return None


def section_units(b: Builder, at: int) -> list[Unit]:
    """The units under the heading of unit ``at`` (its section)."""
    heading = b.manual.units[at].heading
    return [u for u in b.manual.units if u.heading == heading]


def _cycled(b: Builder, proc: _Procedure, at: int) -> tuple[str, Any] | None:
    """The setting a key steps when pressed again: the codes its section's chart lists ("C-1 …
    C-4"), the programmes a numbered chart names, or the amounts of the noun it picks printed
    as a run ("output … 900 / 800 / … / 100 W")."""
    token = proc.key.token
    section = section_units(b, proc.first)
    codes: list[str] = []
    for unit in section:
        if unit.cells and (m := CODE_RE.fullmatch(unit.cells[0].strip())):
            codes.append(m.group(1))
    if len(codes) >= 2:
        name = b.add_discrete(token, list(dict.fromkeys(codes)), label_of(b, token), None)
        b.note(f"variables.{name}.values", ", ".join(codes), proc.first)
        return name, "next"
    programmes = _numbered_names(section)
    if len(programmes) >= 2:
        name = b.add_discrete(f"{token}_programme", programmes, label_of(b, token), None)
        b.note(f"variables.{name}.values", ", ".join(programmes), proc.first)
        return name, "next"
    picked = [
        m.group(1).lower()
        for i in (at, proc.first)
        if (
            m := _PICKED_NOUN.search(
                b.manual.units[i].cells[-1] if b.manual.units[i].cells else b.manual.units[i].text
            )
        )
    ]
    for noun in picked:
        for unit in b.manual.units:
            if noun not in unit.text.lower() or not (run := _NUMBER_RUN.search(unit.text)):
                continue
            numbers = [int(n) for n in re.findall(r"\d+", run.group(1))]
            low, high = min(numbers), max(numbers)
            step = abs(numbers[1] - numbers[0]) or 1
            name = b.unique(f"{token}_{noun}", b.variables)
            b.variables[name] = {
                "type": "numeric",
                "ranges": [[low, high, step]],
                "unit": run.group(2),
                "wrap": True,
                "label": label_of(b, token),
            }
            lower = numbers[0] > numbers[-1] or re.search(
                r"\blower\b", b.manual.units[at].text, re.I
            )
            if lower:
                b.variables[name]["initial"] = high
            b.note(f"variables.{name}", f"{noun}: {run.group(0)}", b.manual.units.index(unit))
            return name, "prev" if lower else "next"
    return None


def _numbered_names(section: list[Unit]) -> list[str]:
    """Names a chart gives programmes by number ("| No. | Programme | … | No. | Programme |"),
    in the numbers' order."""
    found: dict[int, str] = {}
    for unit in section:
        if not unit.cells or not unit.header:
            continue
        for k, head in enumerate(unit.header):
            if k == 0 or k >= len(unit.cells):
                continue
            if re.search(r"\bprogram|\bmenu|\bfood", head, re.I) and unit.cells[k - 1].isdigit():
                name = plain(unit.cells[k])
                if name and not name[0].isdigit():
                    found[int(unit.cells[k - 1])] = name
    return [found[n] for n in sorted(found)]


def _entered(b: Builder, proc: _Procedure, at: int, shared: dict[str, str]) -> str:
    """The variable a procedure's "Enter the …" step types: one cooking time the keys share, or
    the key's own temperature or weight (its range from that step or the key's section)."""
    text = b.manual.units[at].text
    m = _ENTER_RE.search(text)
    noun = plain(m.group(1)) if m else "value"
    said = set(noun.split())
    if said & _TIME_WORDS:
        if "time" not in shared:
            name = b.unique(
                "cook_time" if "cook" in noun or "cooking" in noun else "time", {**b.variables}
            )
            b.variables[name] = {
                "type": "time",
                "ranges": [["00:00:00", "01:39:59", 1]],
                "format": "mm:ss",
                "entry": {"format": "mm:ss"},
                "label": "TIME",
            }
            b.note(f"variables.{name}", "the time the function keys' procedures enter", at)
            shared["time"] = name
        return shared["time"]
    token = proc.key.token
    kind = "weight" if said & _WEIGHT_WORDS else "temperature"
    units = {"weight": ("g",), "temperature": ("°C", "°F")}[kind]
    ranges = [r for r in find_ranges(text) if r.unit in units]
    if not ranges:
        ranges = [
            r for u in section_units(b, proc.first) for r in find_ranges(u.text) if r.unit in units
        ]
    step = next((r.step for r in ranges if r.step), None)
    if not step and kind == "temperature":
        step = _step_in(text)
    if ranges:
        low, high, unit = min(r.low for r in ranges), max(r.high for r in ranges), ranges[0].unit
    else:
        low, high, unit = (100, 3000, "g") if kind == "weight" else (30, 250, units[0])
    name = b.unique(f"{token}_{kind}", b.variables)
    b.variables[name] = {
        "type": "numeric",
        "ranges": [[low, high, step or 1]],
        "unit": unit,
        "entry": {"format": "number"},
        "label": label_of(b, token),
    }
    if not ranges:
        b.unread.add(name)
    b.note(f"variables.{name}", f"{noun} typed after {label_of(b, token)}", at)
    return name


def _step_in(text: str) -> float | None:
    """ "in steps of 10 °C"."""
    m = re.search(r"\bsteps?\s+of\s+(\d+)", text, re.I)
    return float(m.group(1)) if m else None
