"""A dial whose scale each mode gives in a numbered subsection of its own: "6.1 TTL - flash
exposure compensation … -3.0 to +3.0 in steps of one third", "6.2 M and MULTI - output as a
fraction … 1/128 … 1/1 … In MULTI only the whole stops 1/128, 1/64 … 1/4".

Flashes, meters and lamps with one SELECT dial set what the chosen mode means by it: a
compensation in one mode, a fraction of full power in another. Each mode's scale is printed
under a heading that names the mode (or several: "M and MULTI", with a sentence "In MULTI only
…" narrowing one of them). Read as one list, the dial had the wrong values in every mode. The
dial's setting becomes dependent on the mode, a case per mode with that subsection's values in
order (lowest first: the dial's clockwise turn gives more), each mode keeping its own value
when the manual says so ("Every mode keeps its own output").
"""

from __future__ import annotations

import math
import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.roles_common import turns

_HEADING = re.compile(r"^\s*\d{1,2}\.\d{1,2}\s+([A-Za-z].{1,59}?)(?:\s+[-–—:]\s+|$)")
# a decimal signed or not ("-0.7", "+1.3", "0.0") and a fraction with an optional suffix
# ("1/16", "1/16+0.3")
_DECIMAL = r"[+\-−]?\d{1,2}\.\d"
_FRACTION = r"1/\d{1,4}(?:\+\d\.\d)?"
_VALUE = re.compile(rf"(?<![\w./+\-−])({_FRACTION}|{_DECIMAL})(?![\w/]|\.\d)")
# "-3.0 to +3.0 stops in steps of one third of a stop"
_THIRDS = re.compile(
    rf"({_DECIMAL})\s+to\s+({_DECIMAL})\b[^.]{{0,40}}?\bsteps?\s+of\s+(?:one|a)\s+third\b",
    re.IGNORECASE,
)
# "from 16.0 to 26.0 °C in steps of 0.5 °C": a range stepped otherwise, not a list (review31)
_STEPPED = re.compile(rf"({_DECIMAL})\s+to\s+({_DECIMAL})\b[^.]{{0,40}}?\bsteps?\b", re.IGNORECASE)
_KEEPS = re.compile(r"\b(?:every|each)\s+mode\s+keeps\s+its\s+own\b", re.IGNORECASE)
_NOUN = re.compile(r"\b(?:change|set|adjust|choose)s?\s+the\s+([a-z]{3,})\b", re.IGNORECASE)


def _level(v: str) -> float:
    """Where a value stands on its scale: fractions in stops, decimals as they are."""
    v = v.replace("−", "-")
    if "/" in v:
        base, _, extra = v.partition("+")
        num, den = base.split("/")
        return math.log2(int(num) / int(den)) + (float(extra) if extra else 0.0)
    return float(v)


def _thirds(lo: str, hi: str, signed: bool) -> list[str]:
    """Every third of a stop from lo to hi, written as the manual writes thirds (.3 / .7)."""
    a, b_ = round(_level(lo) * 3), round(_level(hi) * 3)
    out = []
    for k in range(min(a, b_), max(a, b_) + 1):
        whole, rest = divmod(abs(k), 3)
        text = f"{whole}.{(0, 3, 7)[rest]}"
        sign = "-" if k < 0 else "+" if k > 0 and signed else ""
        out.append(sign + text)
    return out


def _sections(b: Builder, modes: dict[str, str]) -> list[tuple[list[str], int, int]]:
    """(modes named, first unit, end unit) of each numbered subsection whose heading names
    modes by their printed names."""
    units = b.manual.units
    heads: list[tuple[int, list[str]]] = []
    for i, u in enumerate(units):
        m = _HEADING.match(u.text)
        if m is None:
            continue
        named = [
            modes[w.upper()]
            for w in re.split(r"\s*(?:,|/|\band\b|&)\s*", m.group(1).strip())
            if w.upper() in modes
        ]
        heads.append((i, named))
    out = []
    for k, (i, named) in enumerate(heads):
        end = heads[k + 1][0] if k + 1 < len(heads) else min(len(units), i + 12)
        if named:
            out.append((named, i, end))
    return out


def _scale(text: str) -> list[str]:
    thirds = _THIRDS.search(text)
    if thirds is None and _STEPPED.search(text):
        return []  # (its ends and its step are no three values of a list)
    found = [v.replace("−", "-") for v in _VALUE.findall(text)]
    if thirds:  # (a fraction there is a step's size, "one and 1/3 more")
        signed = any(v.startswith("+") for v in found)
        found = [v for v in found if "/" not in v]
        found += _thirds(thirds.group(1), thirds.group(2), signed)
    elif sum("/" in v for v in found) >= 3:
        found = [v for v in found if "/" in v]  # (fractions: the decimals are their suffixes)
    seen: dict[float, str] = {}
    for v in found:
        seen.setdefault(round(_level(v), 3), v)
    return [seen[k] for k in sorted(seen)]


def read_mode_scales(b: Builder) -> None:
    """Give a turned dial's setting a case per mode from the modes' own subsections."""
    for var, spec in list(b.variables.items()):
        if spec.get("depends_on") or spec.get("type") not in ("discrete", "numeric"):
            continue
        dial = _turned_by(b, var)
        if dial is None:
            continue
        for parent, pspec in b.variables.items():
            if parent == var or pspec.get("type") != "discrete" or parent == "power":
                continue
            modes = {str(v).upper(): str(v) for v in pspec.get("values") or []}
            if len(modes) < 2:
                continue
            cases = _cases(b, modes)
            if cases is None or set(cases) != set(modes.values()):
                continue
            at = min(start for _, start, _ in _sections(b, modes))
            _apply(b, var, spec, parent, cases, dial, at)
            return


def _turned_by(b: Builder, var: str) -> str | None:
    """The dial token whose two turns step the setting, if any."""
    for steps in b.features.values():
        for st in steps:
            eff = st.get("effect")
            if st.get("variable") != var or not isinstance(eff, dict):
                continue
            infos = [i for i in b.infos if i.name in eff and i.skill.startswith("turn")]
            if infos and len(infos) == len(eff):
                cw, ccw = turns(infos)
                if cw and ccw:
                    return infos[0].controls[0]
    return None


def _cases(b: Builder, modes: dict[str, str]) -> dict[str, list[str]] | None:
    units = b.manual.units
    cases: dict[str, list[str]] = {}
    for named, start, end in _sections(b, modes):
        text = " ".join(u.text for u in units[start:end])
        text = re.sub(r"^\s*\d{1,2}\.\d{1,2}\s+", "", text)  # (the heading's own number)
        own: dict[str, list[str]] = {}
        if len(named) > 1:  # "In MULTI only the whole stops 1/128, 1/64 … are available"
            for mode in named:
                printed = next(k for k, v in modes.items() if v == mode)
                m = re.search(rf"\bIn\s+{re.escape(printed)}\s+only\b([^.]*(?:\.\d[^.]*)*)", text)
                if m:
                    own[mode] = _scale(m.group(1))
                    text = text.replace(m.group(0), " ")
        full = _scale(text)
        for mode in named:
            values = own.get(mode) or full
            if len(values) >= 3 and mode not in cases:
                cases[mode] = values
    return cases or None


def _apply(
    b: Builder,
    var: str,
    spec: dict[str, Any],
    parent: str,
    cases: dict[str, list[str]],
    dial: str,
    at: int | None,
) -> None:
    for key in ("values", "ranges", "initial", "unit", "show"):
        spec.pop(key, None)
    spec["type"] = "discrete"
    spec["depends_on"] = parent
    spec["cases"] = {mode: {"values": values} for mode, values in cases.items()}
    for mode, start in _starts(b, b.variables[parent], cases).items():
        spec["cases"][mode]["initial"] = start
    spec["wrap"] = False
    if any(_KEEPS.search(u.text) for u in b.manual.units):
        spec["remember"] = True
    b.unread.discard(var)
    b.note(f"variables.{var}.cases", f"a scale per {parent}: {len(cases)} cases", at)
    if dial in b.labels:  # "Turn it to change the output shown": named by what it changes
        printed = re.compile(rf"(?<!\w){re.escape(b.labels[dial].text.strip())}(?!\w)")
        units = b.manual.units
        for i, u in enumerate(units):
            if not printed.search(u.text):
                continue
            said = " ".join(x.text for x in units[i : i + 2])  # ("SELECT dial. Turn it to …")
            if not re.search(r"\bturn\s+it\b", said, re.IGNORECASE):
                continue
            m = _NOUN.search(said)
            if m and m.group(1).lower() not in b.variables:
                _rename(b, var, m.group(1).lower())
                return


_FACTORY = re.compile(r"\b(?:factory|default|as\s+delivered|new\s+\w+\s+starts?)\b", re.I)


def _starts(b: Builder, pspec: dict[str, Any], cases: dict[str, list[str]]) -> dict[str, str]:
    """Each mode's start value from a sentence of factory values naming every mode with one of
    its own values ("Factory values: TTL 0.0, M 1/1, MULTI 1/32.")."""
    printed = {str(v): str(v).upper() for v in pspec.get("values") or []}
    shows = pspec.get("show")
    if isinstance(shows, dict):
        printed.update({str(k): str(v) for k, v in shows.items() if v})
    for unit in b.manual.units:
        if not _FACTORY.search(unit.text):
            continue
        out = {}
        for mode, values in cases.items():
            name = re.escape(printed.get(mode, mode.upper()))
            alts = "|".join(re.escape(v) for v in sorted(values, key=len, reverse=True))
            m = re.search(rf"(?<![\w/]){name}\s+({alts})(?![\w/+]|\.\d)", unit.text)
            if m:
                out[mode] = m.group(1)
        if len(out) == len(cases):
            return out
    return {}


def _rename(b: Builder, var: str, new: str) -> None:
    b.variables = {(new if n == var else n): s for n, s in b.variables.items()}
    for steps in b.features.values():
        for st in steps:
            if st.get("variable") == var:
                st["variable"] = new
    b.indicators = [new if v == var else v for v in b.indicators]
    b.variables[new]["label"] = new.upper()
