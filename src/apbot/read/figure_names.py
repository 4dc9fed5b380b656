"""Figures a chart names: a key that steps through printed figures ("3000K → 4500K → 6500K")
whose manual also lists it by names, a chart pairing each name with its figure row by row
("WARM  3000K  yellowish …", "NEUTRAL  4500K …"). A user asks for the name ("warm light") as
often as for the figure, and the names are the setting's values; the figures are what the lamps
or the display print for them, kept as each value's display."""

from __future__ import annotations

import re

from apbot.read.text import Unit

_FIGURE = re.compile(r"\s*(\d[\d.,]*)\s*([A-Za-z°%]{0,4})\s*")
_NAME = re.compile(r"[A-Za-z][A-Za-z '-]{1,24}")


def _figure_key(text: str) -> str | None:
    m = _FIGURE.fullmatch(text)
    return f"{m.group(1)}{m.group(2).lower()}" if m else None


def figures_named(figures: list[str], names: list[str], units: list[Unit]) -> dict[str, str] | None:
    """Each name's figure, where one table row holds the name in a cell and the figure in
    another for every one of them (the same count of each, every figure with a unit or none
    alike); None where the chart does not pair them all."""
    if len(figures) != len(names) or len(figures) < 2:
        return None
    keys = [_figure_key(f) for f in figures]
    if any(k is None for k in keys) or not all(_NAME.fullmatch(n.strip()) for n in names):
        return None
    wanted = {k: f for k, f in zip(keys, figures, strict=True) if k is not None}
    lowered = {n.strip().lower(): n for n in names}
    pairs: dict[str, str] = {}
    for unit in units:
        cells = [c.strip() for c in unit.cells]
        named = [c for c in cells if c.lower() in lowered]
        figured = [wanted[k] for c in cells if (k := _figure_key(c)) in wanted]
        if len(named) == 1 and len(figured) == 1:
            pairs.setdefault(named[0].lower(), figured[0])
    if len(pairs) != len(names) or len(set(pairs.values())) != len(names):
        return None
    return pairs
