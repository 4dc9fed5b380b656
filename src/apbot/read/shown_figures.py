"""Values listed as one display word and a figure: "SPM OFF → SPM 20 → SPM 24 → SPM 28".

A display often prints a setting as a short word and the value ("SPM 24", "LV 3"); a list of
its values copied from the display repeats the word in every item. The figure is what a person
names ("an alert at 24"), the word only what the display puts before it: the values are the
figures (or off / on), each shown as printed.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder

_FIGURE_OR_OFF = re.compile(r"\d+(?:\.\d+)?|off|on|--")


def prefixed_figures(values: list[str]) -> dict[str, str] | None:
    """The values of a list whose every item is one display word and a figure ("SPM OFF, SPM
    20, SPM 24 …", "LV 1 … LV 5"), each shown as printed: the figure (or off / on) is the
    value a person names ("an alert at 24"), the word only what the display puts before it.
    None when the items do not all share one leading word before a figure."""
    if len(values) < 3:
        return None
    parts = [v.split(" ", 1) for v in values]
    if any(len(p) != 2 for p in parts) or len({p[0] for p in parts}) != 1:
        return None
    word, rests = parts[0][0], [p[1] for p in parts]
    if not re.fullmatch(r"[a-z]{2,6}", word) or len(set(rests)) != len(rests):
        return None
    if not all(_FIGURE_OR_OFF.fullmatch(r) for r in rests):
        return None
    if not any(r[0].isdigit() for r in rests):
        return None
    return {r: f"{word} {r}".upper() for r in rests}


def read_prefixed_figures(b: Builder) -> None:
    """Give every discrete setting still listed as word-and-figure items (no other stage read
    how they are shown, nor a unit in them) the figures as values, shown as printed."""
    for var, spec in b.variables.items():
        if spec.get("type") != "discrete" or spec.get("show"):
            continue
        figures = prefixed_figures([str(v) for v in spec.get("values") or []])
        if figures is None:
            continue
        old = [str(v) for v in spec["values"]]
        spec["values"], spec["show"] = list(figures), figures
        if spec.get("initial") in old:
            spec["initial"] = list(figures)[old.index(spec["initial"])]
        b.note(
            f"variables.{var}.values", "the figures after the display's word " + old[0].split()[0]
        )
