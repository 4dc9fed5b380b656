"""A setting of numbered levels the manual gives only as a legend of bars: "▮▮▯▯▯  level 2".

A lamp panel with no figures shows a setting's level as a bar of lit and dark segments, and the
manual prints the legend once, a bar and the level it stands for on each line ("▮▯▯▯▯  level 1 -
slowest" … "▮▮▮▮▮  level 5 - fastest"), under a sentence naming the setting ("The speed bar
shows the level by the number of lit segments:"). Where no sentence gives the setting a range
(its range is a guess), that legend is its scale: the levels it numbers, each shown as its bar.
:mod:`apbot.read.shown_bars` pairs bars with values already read; this rule reads the values
from the bars themselves.

A legend counts when it numbers three levels or more in a run (1, 2, 3 …), each bar as long as
the others with exactly as many segments lit as its number, and the setting's own name stands
on one of the three lines above it.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.report import Note

_GLYPHS = "▮▯■□▰▱█░●○"
# a bar, then maybe a word for what it counts ("level", "step", the setting's name), a number
_ROW = re.compile(
    rf"^\s*([{_GLYPHS}](?: ?[{_GLYPHS}])+)\s+(?:([A-Za-z]+)\s+)?(\d{{1,2}})(?!\s*[%\w.,])"
)
_COUNTED = frozenset({"level", "step", "stage", "setting", "speed", "power", "no"})
_ABOVE = 3
_MIN_LEVELS = 3


def read_bar_levels(b: Builder) -> None:
    """Read a guessed numeric setting as the levels a counted bar legend numbers."""
    lines = b.manual.glyph_lines
    for var, spec in b.variables.items():
        if spec.get("type") != "numeric" or var not in b.unread or spec.get("show"):
            continue
        if spec.get("cases"):
            continue
        own = set(words(var.replace("_", " "))) | set(words(str(spec.get("label") or "")))
        found = _legend(lines, own)
        if found is None:
            continue
        bars, at = found
        for key in ("ranges", "unit", "format", "initial", "wrap"):
            spec.pop(key, None)
        spec.update(type="discrete", values=list(bars), show=dict(bars), wrap=False)
        b.unread.discard(var)
        shown = ", ".join(f"{v} {s}" for v, s in bars.items())
        b.notes.append(
            Note(f"variables.{var}.values", f"levels of a bar legend: {shown}", at, lines[at - 1])
        )


def _legend(lines: list[str], own: set[str]) -> tuple[dict[str, str], int] | None:
    """The first run of counted bar lines under a line naming the setting: {level: bar}."""
    number = 0
    while number < len(lines):
        start = number
        run: dict[str, str] = {}
        while number < len(lines) and (m := _ROW.match(lines[number])):
            word = (m.group(2) or "").lower()
            if word and word not in _COUNTED and word not in own:
                break
            run[m.group(3)] = m.group(1).replace(" ", "")
            number += 1
        if len(run) >= _MIN_LEVELS and _counts(run):
            above = lines[max(0, start - _ABOVE) : start]
            if any(own & set(words(line)) for line in above):
                return run, start + 1
        number = max(number, start + 1)
    return None


def _counts(run: dict[str, str]) -> bool:
    """Levels 1, 2, 3 … in a run, each bar one length with as many lit segments as its level."""
    levels = [int(v) for v in run]
    if levels != list(range(levels[0], levels[0] + len(levels))) or levels[0] not in (0, 1):
        return False
    bars = list(run.values())
    if len({len(bar) for bar in bars}) != 1:
        return False
    lit = bars[-1][0]
    return all(
        bar[:n] == lit * n and lit not in bar[n:] and len(set(bar[n:])) <= 1
        for n, bar in zip(levels, bars, strict=True)
    )
