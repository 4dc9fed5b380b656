"""A key that flips between two modes printed as lamps, one of them the key's own name, and an
amount whose range, step and start each mode's own paragraph gives.

"PROBE — control by PLATE or by PROBE", "Press PROBE to change from one mode to the other;
the lamp shows PLATE or PROBE", then a paragraph per mode led by its name: "PLATE   the set
point is the plate temperature. Range 25-340 °C. One click changes it by 5 °C. Starting value
100 °C." / "PROBE   … Range 20-120 °C. One click changes it by 1 °C. Starting value 37 °C."
(a scale key, ECO / NORMAL, FINE / COARSE are drawn the same way). The key's sentences hold one
mode's range, so it was read as an amount of its own; it is the choice of mode, and the amount
the paragraphs name (the one read with one of their ranges) takes a case per mode.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import tidy_number
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.text import Unit
from apbot.read.value_steps import find_initial, find_step
from apbot.read.values import NUM, UNIT, Range, find_ranges, number, unit_name

# "PLATE or PROBE", "by PLATE or by PROBE", "PLATE / PROBE"
_TWO_RE = re.compile(r"\b([A-Z][A-Z]{2,})\s+(?:or\s+(?:by\s+)?|/\s*)([A-Z][A-Z]{2,})\b")
_MODE_CUE = re.compile(r"\b(?:mode|lamp|control(?:s|led)?\s+by|change|switch)", re.I)
_STEP_RE = re.compile(
    rf"\b(?:change|move|raise|add|turn)s?\b[^.;]{{0,40}}?\bby\s+({NUM})\s*({UNIT})(?![\w:])"
    rf"|\beach\s+(?:click|press|step)\s+is\s+({NUM})\s*({UNIT})(?![\w:])",
    re.I,
)
_START_MORE = r"|starting value|start value|starts? from"


def _paragraph(units: list[Unit], at: int, value: str, others: list[str]) -> str:
    """The text of the paragraph the value leads: its unit and those right under it, up to a
    unit led by another mode or a gap of more than one line."""
    texts = [units[at].text]
    for k in range(at + 1, min(at + 6, len(units))):
        u, prev = units[k], units[k - 1]
        if u.cells or u.heading != units[at].heading or u.line - prev.line > 1:
            break
        if any(re.match(rf"\W*{re.escape(o)}\s{{2,}}\S", u.text) for o in others):
            break
        texts.append(u.text)
    return " ".join(texts)


def _mode_facts(text: str) -> tuple[Range, float | None, float | None] | None:
    """(range, step, start) a mode's paragraph gives, in the range's unit."""
    ranges = [r for r in find_ranges(text) if r.unit]
    if len(ranges) != 1:
        return None
    r = ranges[0]
    step: float | None = None
    m = _STEP_RE.search(text)
    if m:
        amount, unit = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
        step = number(amount) if unit_name(unit) == r.unit else None
    elif (said := find_step(text)) is not None and said[1] == r.unit:
        step = said[0]
    start = find_initial(text, _START_MORE)
    first = start[0] if start and start[1] in ("", r.unit) else None
    return r, step, first


def _two_modes(b: Builder, token: str) -> tuple[str, str] | None:
    """The two modes the key flips between, one of them its own printed name."""
    label = b.labels[token].text
    for i in b.labels[token].mentions:
        text = b.manual.units[i].text
        for m in _TWO_RE.finditer(text):
            pair = (m.group(1), m.group(2))
            if label in pair and pair[0] != pair[1] and _MODE_CUE.search(text):
                return pair
    return None


def read_mode_cases(b: Builder) -> None:
    """Make a key read as an amount of its own the choice of two modes, and the amount each
    mode's paragraph names depend on it."""
    units = b.manual.units
    for var, spec in list(b.variables.items()):
        feats = [
            (name, f)
            for name, steps in b.features.items()
            for f in steps
            if f.get("variable") == var
        ]
        acts = {a for _, f in feats for a in f.get("actions", [])}
        keys = [i for i in b.infos if i.name in acts]
        if spec.get("type") != "numeric" or len(keys) != 1 or keys[0].skill != "press":
            continue
        token = keys[0].controls[0]
        if token not in b.labels or (modes := _two_modes(b, token)) is None:
            continue
        facts: dict[str, tuple[Range, float | None, float | None]] = {}
        texts: list[str] = []
        for mode in modes:
            other = [o for o in modes if o != mode]
            led = [k for k, u in enumerate(units) if re.match(rf"\W*{mode}\s{{2,}}\S", u.text)]
            paragraphs = [_paragraph(units, k, mode, other) for k in led]
            said = next(((f, t) for t in paragraphs if (f := _mode_facts(t))), None)
            if said is None:
                break
            facts[mode], _ = said
            texts.append(said[1])
        if len(facts) != 2 or len({(r.low, r.high) for r, _, _ in facts.values()}) != 2:
            continue
        target = _target(b, var, facts, " ".join(texts))
        if target is None:
            continue
        _make_choice(b, var, spec, modes, feats)
        _give_cases(b, target, var, facts)
        return


def _target(
    b: Builder, var: str, facts: dict[str, tuple[Range, float | None, float | None]], said: str
) -> str | None:
    """The amount read with one of the modes' ranges (not the key's own), else one whose range
    was guessed, in the modes' unit, that the paragraphs name ("One click of the HEAT knob")."""
    spans = {(r.low, r.high, r.unit) for r, _, _ in facts.values()}
    unit = next(iter(spans))[2]
    guessed: list[str] = []
    for name, spec in b.variables.items():
        ranges = spec.get("ranges") or []
        if name == var or spec.get("type") != "numeric" or spec.get("depends_on"):
            continue
        if len(ranges) == 1 and (ranges[0][0], ranges[0][1], spec.get("unit", "")) in spans:
            return name
        named = {w for w in words(f"{name} {spec.get('label', '')}") if len(w) >= 3}
        if name in b.unread and spec.get("unit") == unit and named & set(words(said)):
            guessed.append(name)
    return guessed[0] if len(guessed) == 1 else None


def _make_choice(
    b: Builder,
    var: str,
    spec: dict[str, Any],
    modes: tuple[str, str],
    feats: list[tuple[str, dict[str, Any]]],
) -> None:
    """The key's variable becomes the choice of the two modes, shown by their lamps."""
    label = spec.get("label", "")
    spec.clear()
    spec.update(
        {
            "type": "discrete",
            "values": [m.lower() for m in modes],
            "label": label,
            "show": {m.lower(): m for m in modes},
        }
    )
    for _, f in feats:
        f["effect"] = "toggle"
    b.note(f"variables.{var}", f"a choice of two modes: {modes[0]} or {modes[1]} (their lamps)")


def _give_cases(
    b: Builder, target: str, var: str, facts: dict[str, tuple[Range, float | None, float | None]]
) -> None:
    spec = b.variables[target]
    own_step = spec["ranges"][0][2]
    cases: dict[str, Any] = {}
    for mode, (r, step, start) in facts.items():
        st = step or own_step
        top = r.low + int((r.high - r.low) / st + 1e-9) * st
        case: dict[str, Any] = {"ranges": [[tidy_number(r.low), tidy_number(top), tidy_number(st)]]}
        if start is not None and r.low <= start <= r.high:
            case["initial"] = tidy_number(start)
        cases[mode.lower()] = case
    for key in ("ranges", "initial", "wrap"):
        spec.pop(key, None)
    spec["depends_on"] = var
    spec["cases"] = cases
    b.note(f"variables.{target}.cases", f"one range per {var}, each mode's own paragraph")
