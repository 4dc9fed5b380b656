"""Settings the display shows as a bar of segments, read from the manual's legend.

Small displays often show a level as a row of filled and empty segments rather than a word:
"▮▯▯ soft   ▮▮▯ medium   ▮▮▮ hard", "▮▯▯▯▯ 20 %  ▮▮▯▯▯ 40 % …". The text cleaner drops such
glyphs from the units, so the setting's values are read but not how they look; the loop then
sees a display it cannot read and keeps pressing. This rule reads the raw lines: a run of two
or more segment glyphs followed by one of a discrete setting's values (the setting's own name
may stand between: "▮▯▯  flow LOW") pairs that value with the bar. Two or more values so
paired, each with its own bar and all bars of one length, become what the display shows; a
numeric setting of a few stepped levels (20–100 % by 20) does so when every level has its bar.
When the same bars pair with several settings of the same values (a fan speed and a dryness,
both LOW / MEDIUM / HIGH), only those named on the bar lines or just above them take them.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.report import Note

_GLYPHS = "▮▯■□▰▱█░●○"  # (dot lamps too: "●○○  2,500 lux")
# (a row of lamps may be printed spaced, "● ○ ○ ○ ○"; the display shows it as one picture)
_BAR_RE = re.compile(
    rf"(?<![{_GLYPHS}])(?<![{_GLYPHS}] )[{_GLYPHS}](?: ?[{_GLYPHS}])+(?! ?[{_GLYPHS}])"
)
# the value right after the bar, or in the next cell of a table row ("| ● ○ ○ | 2700 K |")
_AFTER_RE = re.compile(
    r"[^\S\n]*(?:\|[^\S\n]*)?([A-Za-z0-9][\w+/-]*(?:[^\S\n][A-Za-z0-9][\w+/-]*){0,3})"
)


def read_bar_shows(b: Builder) -> None:
    """Give each setting whose values the manual prints beside bars those bars (a numeric one
    of a few stepped levels, every level with its bar, becomes the list of its levels)."""
    lines = b.manual.glyph_lines
    found: dict[str, tuple[list[str], dict[str, str], int]] = {}
    for var, spec in b.variables.items():
        values = [str(v) for v in spec.get("values") or _case_values(spec)] or _levels(spec)
        if spec.get("type") not in ("discrete", "numeric") or len(values) < 2 or spec.get("show"):
            continue
        if {v.lower() for v in values} <= {"on", "off"}:
            continue
        if _shown_as_figure(lines, str(spec.get("label") or "")):
            continue  # "FIZZ 3   fizz level": the display prints the figure; the bars are lamps
        bars, at = _paired(lines, var, values)
        if len(bars) < 2 or len({len(s) for s in bars.values()}) != 1:
            continue
        if len(set(bars.values())) != len(bars):
            continue
        found[var] = (values, bars, at)
    for var, (values, bars, at) in found.items():
        spec = b.variables[var]
        alike = [v for v in found if found[v][1] == bars]
        if len(alike) > 1 and not _named_near(lines, var, bars, at):
            continue  # the bars of another setting of the same values
        if spec["type"] == "numeric":  # "▮▯▯▯▯ 20 %  ▮▮▯▯▯ 40 % …": a few levels, each a bar
            if len(bars) < len(values):
                bars = _counted(bars, values)  # "▮▮▯▯ level 2": level n is n lamps lit
            if len(bars) < len(values):
                continue
            _as_levels(spec, values)
        spec["show"] = {v: bars[v] for v in values if v in bars}
        shown = ", ".join(f"{v} {s}" for v, s in spec["show"].items())
        quote = lines[at - 1].strip()[:160]
        b.notes.append(Note(f"variables.{var}.show", f"shown as bars: {shown}", at, quote))


def _shown_as_figure(lines: list[str], label: str) -> bool:
    """A display legend line that gives the setting as its name and a figure ("FIZZ 3   fizz
    level while the knob is turned"): the display prints the level, whatever lamps beside it
    show as bars."""
    if len(label) < 2:
        return False
    row = re.compile(rf"^\s*{re.escape(label)}\s\d{{1,3}}\s{{2,}}[A-Za-z]")
    return any(row.match(line) for line in lines)


def _case_values(spec: dict[str, Any]) -> list[str]:
    """Every value a per-programme choice has in some programme, in the order first met
    (intensity low / medium / high in one mode, low / medium in another)."""
    if spec.get("type") != "discrete":
        return []
    cases = spec.get("cases") or {}
    return list(dict.fromkeys(str(v) for c in cases.values() for v in c.get("values") or []))


def _paired(lines: list[str], var: str, values: list[str]) -> tuple[dict[str, str], int]:
    """Each value the lines print right after a bar, with that bar (a value printed after two
    different bars is dropped), and the line of the first pairing."""
    own = set(words(var.replace("_", " ")))
    by_words = {tuple(words(v)): v for v in values}
    found: dict[str, set[str]] = {}
    first = 0
    for n, line in enumerate(lines, start=1):
        line = re.sub(r"(?<=\d),(?=\d{3}\b)", "", line)  # "●○○  2,500 lux": 2500
        for m in _BAR_RE.finditer(line):
            after = _AFTER_RE.match(line, m.end())
            if after is None:
                continue
            ws = words(after.group(1))
            if ws and (ws[0] in own or ws[0] in _LEVEL_WORDS):
                ws = ws[1:]  # "▮▯▯  flow LOW": the setting's own name, then the value
                # ("SENS ▮▯▯▯  level 1": the word for a level, then its figure)
            value = next(
                (by_words[tuple(ws[:k])] for k in (3, 2, 1) if tuple(ws[:k]) in by_words), None
            )
            if value is not None:
                found.setdefault(value, set()).add(m.group(0).replace(" ", ""))
                first = first or n
    return {v: next(iter(s)) for v, s in found.items() if len(s) == 1}, first


# words a legend prints before a bar's figure ("level 1", "step 4"): no part of the value
_LEVEL_WORDS = frozenset({"level", "step", "stage"})


def _named_near(lines: list[str], var: str, bars: dict[str, str], at: int) -> bool:
    """The setting's own name is on a line of its bars or on one of the three lines above the
    first ("The fan speed is shown as bars:")."""
    own = set(words(var.replace("_", " ")))
    near = lines[max(at - 4, 0) : at] + [ln for ln in lines if any(s in ln for s in bars.values())]
    return any(own & set(words(ln)) for ln in near)


def _counted(bars: dict[str, str], values: list[str]) -> dict[str, str]:
    """Bars that count their level (level n: n lamps lit, the rest dark, all bars one length),
    printed for some levels only ("level 1", "level 4", "level 8"): every level's bar, by the
    same count; the bars as they are when they do not count so."""
    if not bars:
        return bars
    first = next(iter(bars.values()))
    lit, dark, length = first[0], "", len(first)
    for v, bar in bars.items():
        n = int(v) if v.isdigit() else -1
        if not 0 < n <= length or bar != lit * n + bar[n:] or len(set(bar[n:])) > 1:
            return bars
        dark = dark or bar[n : n + 1]
    if len(bars) < 3 or not dark or dark == lit:
        return bars
    if not all(v.isdigit() and 0 < int(v) <= length for v in values):
        return bars
    return {v: lit * int(v) + dark * (length - int(v)) for v in values}


def _levels(spec: dict[str, Any]) -> list[str]:
    """A numeric setting's few values, when it has one stepped range (20–100 % by 20); with a
    range per case ("1 – 8" in CLEANSE, "1 – 4" in SENSITIVE), every case's levels."""
    if spec.get("type") == "numeric" and spec.get("cases") and not spec.get("ranges"):
        found: list[str] = []
        for case in spec["cases"].values():
            own = _levels({"type": "numeric", "ranges": case.get("ranges") or []})
            if not own:
                return []
            found += [v for v in own if v not in found]
        return sorted(found, key=float) if len(found) <= 12 else []
    ranges = spec.get("ranges") or []
    if spec.get("type") != "numeric" or not ranges or spec.get("cases"):
        return []
    levels: list[str] = []  # (uneven pieces too: 2500–5000 by 2500, 5000–10000 by 5000)
    for low, high, step in ranges:
        if not isinstance(step, int | float) or step <= 0 or (high - low) / step > 12:
            return []
        count = round((high - low) / step)
        levels += [x for k in range(count + 1) if (x := f"{low + k * step:g}") not in levels]
    return levels if len(levels) <= 12 else []


def _as_levels(spec: dict[str, Any], values: list[str]) -> None:
    """The numeric setting becomes the list of its levels (what a bar can show)."""
    for key in ("ranges", "unit", "format"):
        spec.pop(key, None)
    spec["type"] = "discrete"
    spec["values"] = values
    for case in (spec.get("cases") or {}).values():  # each case its own levels
        own = _levels({"type": "numeric", "ranges": case.pop("ranges", None) or []})
        case["values"] = own or values
        if "initial" in case and isinstance(case["initial"], float | int):
            case["initial"] = f"{case['initial']:g}"
    if spec.get("cases"):
        spec.pop("values")  # (the cases hold the domains)
    if "initial" in spec:
        spec["initial"] = (
            f"{spec['initial']:g}" if isinstance(spec["initial"], float | int) else spec["initial"]
        )
