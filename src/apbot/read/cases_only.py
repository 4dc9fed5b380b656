"""A setting that exists in one mode only: "HOURS  Chooses the run time (DUSK + TIMER mode
only)", "The run time applies only to the DUSK + TIMER mode".

Manuals often give a key a number that only one value of a mode selector uses — a run time for
a timed mode, a custom target for the CUSTOM programme — and say so in the key's legend row
("(<MODE> only)") or a sentence ("applies only to <MODE>", "works only in <MODE>"). Read on its
own the number looks always adjustable; the planner then presses the key in the wrong mode and
the appliance refuses it. The setting becomes a case of that mode: its range is that case's.

They also often say where the number starts each time the mode is chosen ("Whenever DUSK +
TIMER is selected with MODE, the run time starts again at 4 h"): that case's start value.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.values import NUM, number

_NUMERIC = frozenset({"numeric", "time"})
# what is named before the mode: "(DUSK + TIMER mode only)", "applies only to the X mode"
_ONLY_AFTER = r"\s*(?:mode|programme|program|setting|function)?\s+only\b"
_ONLY_BEFORE = (
    r"\b(?:appl(?:y|ies)|works?|is\s+used|can\s+be\s+(?:set|used|chosen)|available)\s+only\s+"
    r"(?:to|in|with|for)\s+(?:the\s+)?"
)
_START = r"\b(?:starts?|begins?)\s+(?:again\s+)?(?:at|from)\s+|\b(?:goes|go)\s+back\s+to\s+"
_START += r"|\b(?:returns?|is\s+reset)\s+to\s+"
_STARTS = r"\b(?:starts?|default|factory)\b"
_CHOSEN = r"\b(?:selected|chosen|choose|select)\b"


def _value_pattern(value: str) -> str:
    """The value as a manual writes it: any case, any spacing ("dusk + timer", "DUSK+TIMER")."""
    parts = [re.escape(p) for p in re.findall(r"[a-z0-9]+|[^\sa-z0-9]", value.lower())]
    return r"(?<![\w+])" + r"\s*".join(parts) + r"(?![\w+])"


def _mentions(b: Builder, name: str, spec: dict[str, Any]) -> list[tuple[int, str]]:
    """The texts that speak of the setting: its key's legend rows and sentences naming its
    label (the key as printed) or its name."""
    label = str(spec.get("label") or "")
    keys = [label] if label and len(label) >= 2 else []
    keys += [w for w in name.split("_") if len(w) >= 4]
    pattern = "|".join(rf"(?<![A-Za-z]){re.escape(k)}(?![A-Za-z])" for k in keys)
    if not pattern:
        return []
    return [(i, u.text) for i, u in enumerate(b.manual.units) if re.search(pattern, u.text, re.I)]


def _only_mode(texts: list[tuple[int, str]], values: list[str]) -> tuple[str, int] | None:
    """The one mode value these texts say the setting works in only, and the unit saying it;
    None when none or two."""
    texts = [(i, t) for i, t in texts if "only" in t.lower()]  # both patterns need it
    if not texts:
        return None  # (compiling a pattern per value was a tenth of reading the manuals)
    found: dict[str, int] = {}
    for value in values:
        v = _value_pattern(value)
        only = re.compile(rf"\(\s*{v}{_ONLY_AFTER}\s*\)|{_ONLY_BEFORE}{v}", re.I)
        at = next((i for i, t in texts if only.search(t)), None)
        if at is not None:
            found[value] = at
    # "(NIGHT + TIMER mode only)" names NIGHT + TIMER, not the NIGHT inside it
    found = {v: at for v, at in found.items() if not any(v != w and v in w for w in found)}
    return next(iter(found.items())) if len(found) == 1 else None


def _start_value(b: Builder, value: str, spec: dict[str, Any]) -> float | None:
    """The number a sentence says the setting starts at whenever the mode value is chosen,
    in the setting's own unit ("Whenever X is selected …, the run time starts again at 4 h")."""
    unit = str(spec.get("unit") or "")
    v = _value_pattern(value)
    for u in b.manual.units:
        text = u.text
        if not re.search(v, text, re.I) or not re.search(_CHOSEN, text, re.I):
            continue
        m = re.search(rf"(?:{_START})({NUM})\s*([a-z°%]*)", text, re.I)
        if m is None:
            continue
        said = m.group(2).lower()
        if unit and said and not (said.startswith(unit.lower()) or unit.lower().startswith(said)):
            continue
        return number(m.group(1))
    return _said_start(b, v, spec)


def _said_start(b: Builder, v: str, spec: dict[str, Any]) -> float | None:
    """The number a sentence on how the appliance starts gives the setting in that mode ("The
    humidifier starts in AUTO mode with a target humidity of 50 %"): a sentence naming the
    mode, the setting and a start, with one number in the setting's unit inside its range."""
    unit = str(spec.get("unit") or "")
    names = [w for w in str(spec.get("_name") or "").split("_") if len(w) >= 4]
    if spec.get("type") != "numeric" or not unit or not names:
        return None
    for u in b.manual.units:
        text = u.text
        if not re.search(v, text, re.I) or not re.search(_STARTS, text, re.I):
            continue
        if not any(re.search(rf"\b{re.escape(n)}", text, re.I) for n in names):
            continue
        said = {
            number(m.group(1))
            for m in re.finditer(rf"({NUM})\s*{re.escape(unit)}(?![a-z])", text, re.I)
        }
        inside = {x for x in said if x is not None and _inside(spec, x)}
        if len(inside) == 1:
            return inside.pop()
    return None


def _inside(spec: dict[str, Any], value: float) -> bool:
    for lo, hi, *_ in spec.get("ranges") or []:
        try:
            if float(lo) <= value <= float(hi):
                return True
        except (TypeError, ValueError):
            return False
    return False


def read_only_modes(b: Builder) -> None:
    """Make each number the manual says works in one mode only a case of that mode."""
    modes = {
        name: [str(v) for v in spec.get("values") or []]
        for name, spec in b.variables.items()
        if spec.get("type") == "discrete"
        and not spec.get("depends_on")
        and len(spec.get("values") or []) >= 3
        and name not in ("power", "running")
    }
    for name, spec in b.variables.items():
        if spec.get("type") not in _NUMERIC or spec.get("depends_on") or "cases" in spec:
            continue
        if not spec.get("ranges") or name in b.unread:
            continue
        texts = _mentions(b, name, spec)
        hits = [(mode, h) for mode, vs in modes.items() if (h := _only_mode(texts, vs))]
        if len(hits) != 1:
            continue
        mode, (value, at) = hits[0]
        case: dict[str, Any] = {"ranges": spec.pop("ranges")}
        start = _start_value(b, value, {**spec, "ranges": case["ranges"], "_name": name})
        if start is not None and _inside(case, start):
            case["initial"] = int(start) if float(start).is_integer() else start
        elif "initial" in spec:
            case["initial"] = spec["initial"]
        spec.pop("initial", None)
        spec["depends_on"] = mode
        spec["cases"] = {value: case}
        b.note(f"variables.{name}.cases", f"set only in {mode} {value}", at)
