"""A setting one mode holds at a fixed value, said in prose: "In Sleep mode the speed is fixed at
1", "in STERILIZE mode the temperature is fixed at 100 °C", "In night mode the mist output is
fixed to I", "In ECO mode the heat output is limited to 750 W".

Manuals say such a thing once, in the mode's sentence, not in the setting's. Read without it,
the setting looks adjustable in every mode: the planner steps it in the mode that holds it and
the display never moves. The setting becomes dependent on the mode: in that mode's case its
only value is the fixed one; in every other case its domain as read.
"""

from __future__ import annotations

import copy
import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.labels import CONTROL_NOUNS, words
from apbot.read.values import NUM, number

# "In Sleep mode the speed …", "In the ECO mode, the heat output …", "While in NIGHT mode …"
_IN_MODE = re.compile(
    r"\b(?:in|during|while\s+in)\s+(?:the\s+)?(?P<mode>[A-Za-z][\w+ -]{0,20}?)\s+"
    r"(?:mode|programme|program|setting|function)\b,?\s+(?P<rest>[^.;]+)",
    re.IGNORECASE,
)
# "… is fixed at", "is locked to", "is limited to", "stays at", "runs at", "is always"
_HELD = re.compile(
    r"^(?P<subject>.{0,40}?)\b(?:(?:is|are|stays?|remains?)\s+(?:fixed|locked|limited|set|held)"
    r"\s+(?:at|to)|(?:stays?|remains?|runs?|works?|operates?)\s+(?:at|on)|(?:is|are)\s+always)"
    r"\s+(?:(?:the\s+)?(?P<again>[a-z]+)\s+)?(?P<value>[^\s,;:()]+)",
    re.IGNORECASE,
)

# "GREEK uses a fixed time of 12 hours", "The ECO programme has a fixed temperature of 40 °C":
# the mode named first, then the setting it holds and the value
_USES_FIXED = re.compile(
    r"\b(?P<mode>[A-Za-z][\w+-]*(?:\s+[A-Za-z][\w+-]*)?)\s+(?:mode\s+|programme\s+|program\s+)?"
    r"(?:always\s+)?(?:uses|has|runs\s+(?:with|at)|works\s+(?:with|at)|keeps)\s+a\s+"
    r"(?:fixed|set|constant)\s+(?P<subject>[a-z][a-z ]{1,30}?)\s+(?:of|at)\s+"
    r"(?P<value>[^\s,;:()]+)",
    re.IGNORECASE,
)


def _own_words(name: str, spec: dict[str, Any]) -> set[str]:
    said = words(name.replace("_", " ")) + words(str(spec.get("label") or ""))
    return {w for w in said if len(w) >= 3 and not re.fullmatch(CONTROL_NOUNS, w)}


def _names(subject: set[str], own: set[str]) -> bool:
    """The sentence's subject names the setting: one of its words, or a longer word one of
    them begins ("temperature" for TEMP)."""
    return any(w == o or (len(o) >= 4 and w.startswith(o)) for w in subject for o in own)


def _parent(b: Builder, mode: str, child: str) -> tuple[str, str] | None:
    """The independent discrete setting and the value the mode's name says: a value of a list
    ("Sleep" of MODE) or a toggle named so ("ECO" → eco on)."""
    said = mode.strip().lower()
    found: list[tuple[str, str]] = []
    for name, spec in b.variables.items():
        if name == child or spec.get("type") != "discrete" or spec.get("depends_on"):
            continue
        if name in ("power", "running"):
            continue
        values = [str(v) for v in spec.get("values") or []]
        if said in values and said not in ("on", "off"):
            found.append((name, said))
        elif values == ["off", "on"] and said in {
            name.replace("_", " "),
            str(spec.get("label") or "").lower(),
        }:
            found.append((name, "on"))
    return found[0] if len(found) == 1 else None


def _last_words(b: Builder, mode: str, child: str) -> str:
    """The mode's name from the words before the verb: the whole run when it names a value,
    else its last word ("The GREEK" → "GREEK")."""
    if _parent(b, mode, child) is not None or " " not in mode.strip():
        return mode
    return mode.split()[-1]


def _held_value(spec: dict[str, Any], said: str) -> Any:
    """The value said, when it is one of the setting's own (a listed name, a number on its
    grid)."""
    if spec.get("type") == "discrete":
        plain = said.strip().lower()
        values = [str(v) for v in spec.get("values") or []]
        return plain if plain in values and plain not in ("on", "off") else None
    if spec.get("type") != "numeric":
        return None
    m = re.match(rf"({NUM})", said)
    value = number(m.group(1)) if m else None
    if value is None:
        return None
    for lo, hi, *rest in spec.get("ranges") or []:
        step = float(rest[0]) if rest else 1.0
        if float(lo) <= value <= float(hi) and abs((value - float(lo)) / step % 1) < 1e-9:
            return int(value) if float(value).is_integer() else value
    return None


def read_fixed_in_mode(b: Builder) -> None:
    """Make each setting a mode's sentence says it holds at one value dependent on that mode."""
    for i, unit in enumerate(b.manual.units):
        said: list[tuple[str, set[str], str]] = []
        for m in _IN_MODE.finditer(unit.text):
            held = _HELD.match(m.group("rest"))
            if held is not None:
                subject = set(words(held.group("subject"))) | set(words(held.group("again") or ""))
                said.append((m.group("mode"), subject, held.group("value")))
        for m in _USES_FIXED.finditer(unit.text):
            said.append((m.group("mode"), set(words(m.group("subject"))), m.group("value")))
        for mode, subject, told in said:
            for name, spec in b.variables.items():
                if spec.get("depends_on") or "cases" in spec or name in b.unread:
                    continue
                if name in ("power", "running") or not _names(subject, _own_words(name, spec)):
                    continue
                value = _held_value(spec, told)
                parent = _parent(b, _last_words(b, mode, name), name) if value is not None else None
                if parent is None:
                    continue
                _make_cases(b, name, spec, parent, value, i)
                break


def _make_cases(
    b: Builder, name: str, spec: dict[str, Any], parent: tuple[str, str], value: Any, at: int
) -> None:
    mode, chosen = parent
    own = {k: spec.pop(k) for k in ("values", "ranges", "initial") if k in spec}
    cases: dict[str, Any] = {}
    for v in b.variables[mode].get("values") or []:
        if str(v) == chosen:
            held: dict[str, Any] = (
                {"values": [value]} if "values" in own else {"ranges": [[value, value, 1]]}
            )
            cases[str(v)] = {**held, "initial": value}
        else:
            cases[str(v)] = copy.deepcopy(own)
    spec["depends_on"] = mode
    spec["cases"] = cases
    b.note(f"variables.{name}.cases", f"fixed at {value} in {mode} {chosen}", at)
