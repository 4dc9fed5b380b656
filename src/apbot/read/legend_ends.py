"""Two keys of one setting named for its two ends: SPIN BACK / SPIN TOP over a legend of codes.

A panel may step one setting with a pair of keys named by the setting and by what each end of
its scale is called (spin_back / spin_top, tone_bass / tone_treble, zoom_wide / zoom_tele) rather
than by a direction (up / down, + / −). The manual then prints the setting's values as a legend, a
line per value led by the code the display shows ("B3   heavy backspin", "0   no spin", "T3
heavy topspin"). The legend's order is the scale's order, and its glosses say which end each key
words: the rows glossed with "back…" are one key's end, those with "top…" the other's. Such a
pair steps ONE setting over the legend's codes, the key of the later rows forward, the other one
back, stopping at the ends (a scale, not a cycle).

The legend must sit under a line naming the setting (the 3 lines before it), its rows must be
short codes with a gloss, each key's word must begin a gloss word of one end only, and the two
ends' rows must not interleave — so a table of codes glossed otherwise is not taken.
"""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.code_words import own_lines
from apbot.read.labels import words
from apbot.read.off_words import unit_at
from apbot.read.shapes import adjuster_direction

# a legend row: a short code, two spaces or more, then its gloss ("B3   heavy backspin")
_ROW = re.compile(r"^\s*([A-Za-z]{0,2}\d{0,2}[+-]?)\s{2,}([A-Za-z][^|]{2,60})$")
_BEFORE = 3  # lines above the legend that may name the setting
_MIN_ROWS = 3


def legend_end_pairs(b: Builder, infos: list[ActionInfo], done: set[str]) -> set[str]:
    """Read each such pair of keys as one stepped setting; the actions taken."""
    groups: dict[str, list[tuple[str, ActionInfo]]] = {}
    for info in infos:
        parts = info.token.split("_")
        if info.name in done or len(parts) < 2 or adjuster_direction(info) is not None:
            continue  # (▲ / ▼, + / − keys are the stepping pairs' own job)
        if info.skill != "press" or info.digit is not None:
            continue
        groups.setdefault("_".join(parts[:-1]), []).append((parts[-1], info))
    taken: set[str] = set()
    lines = own_lines(b)
    for base, keys in groups.items():
        if len(keys) != 2 or keys[0][0] == keys[1][0]:
            continue
        found = _legend(lines, base)
        if not found:
            continue
        codes, glosses, at = found
        ends = [_rows(glosses, word) for word, _ in keys]
        if not ends[0] or not ends[1] or ends[0] & ends[1]:
            continue
        if max(ends[0]) < min(ends[1]):
            down, up = keys[0][1].name, keys[1][1].name
        elif max(ends[1]) < min(ends[0]):
            down, up = keys[1][1].name, keys[0][1].name
        else:
            continue
        var = b.add_discrete(base, codes, base.upper(), None)
        b.variables[var]["wrap"] = False
        b.feature(
            f"set_{var}",
            [{"actions": [up, down], "variable": var, "effect": {up: "next", down: "prev"}}],
        )
        b.note(
            f"variables.{var}.values",
            f"a legend of codes, its ends named by the keys: {', '.join(codes)}",
            unit_at(b, at),
        )
        taken |= {up, down}
    return taken


def _legend(lines: list[str], base: str) -> tuple[list[str], list[str], int] | None:
    """The first run of legend rows under a line naming ``base``: codes, glosses, first line."""
    noun = set(base.split("_"))
    number = 0
    while number < len(lines):
        run: list[tuple[str, str]] = []
        start = number
        while number < len(lines) and (m := _ROW.match(lines[number])) and m.group(1):
            run.append((m.group(1), m.group(2).strip()))
            number += 1
        if len(run) >= _MIN_ROWS and any(
            noun & set(words(lines[i])) for i in range(max(0, start - _BEFORE), start)
        ):
            codes = [c for c, _ in run]
            if len(set(codes)) == len(codes):
                return codes, [g for _, g in run], start + 1
        number = max(number, start + 1)
    return None


def _rows(glosses: list[str], word: str) -> set[int]:
    """The rows whose gloss has a word beginning with the key's word ("back" → "backspin")."""
    if len(word) < 3 or not word.isalpha():
        return set()
    return {i for i, g in enumerate(glosses) if any(w.startswith(word) for w in words(g))}
