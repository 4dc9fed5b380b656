"""Between settings that fit the sentence's words equally well, the one the user means — told by
something meaningful, never by the order the belief happens to list its settings in.

Two settings of a read belief can offer the same value (a STYLE key and a PRINT key both read as
stepping NORMAL → BOLD → ITALIC) while the sentence ("italic text") names neither. The manual
does: it lists a key's values where it explains that key ("Press STYLE repeatedly: NORMAL →
BOLD → ITALIC"). So the setting whose own name the manual prints nearest to the value wins;
then a setting with a key of its own over one reached through another key's steps; then the
order the belief describes its settings in — a read belief's is the manual's, which no listing
of the robot's actions changes.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Hashable, Sequence
from functools import lru_cache
from typing import Any, TypeVar

from apbot.model.schema import ApplianceModel
from apbot.read.goal_view import Model

FAR = 10**6
"""The distance of a setting or value the manual never prints."""

M = TypeVar("M")


def told_apart(
    matches: Sequence[M],
    tie: Callable[[M], Hashable],
    var_of: Callable[[M], str],
    value_of: Callable[[M], Any],
    view: Model,
) -> list[M]:
    """``matches`` (sorted best first) with each run of equally good ones (same ``tie``) that
    spans several settings put in :func:`preference` order, setting by setting; a setting's own
    matches keep their order."""
    out: list[M] = []
    k = 0
    while k < len(matches):
        end = k + 1
        while end < len(matches) and tie(matches[end]) == tie(matches[k]):
            end += 1
        run = list(matches[k:end])
        names = list(dict.fromkeys(var_of(m) for m in run))
        if len(names) > 1:
            rank = {
                name: preference(view, name, [value_of(m) for m in run if var_of(m) == name])
                for name in names
            }
            run.sort(key=lambda m: rank[var_of(m)])  # stable: a setting's matches keep order
        out += run
        k = end
    return out


def preference(view: Model, name: str, values: Sequence[Any]) -> tuple[int, int, int]:
    """How surely ``name`` is meant among equals: nearest in the manual to one of ``values``,
    then a key of its own, then the belief's order of settings."""
    spelled = _names_of(view, name)
    near = min((_distance(view.manual_lines, spelled, str(v)) for v in values), default=FAR)
    info = view.infos.get(name)
    return (near, own_key_depth(view.model, name), info.order if info is not None else FAR)


def own_key_depth(model: ApplianceModel, name: str) -> int:
    """0 when a key's first step sets ``name`` (a key of its own); k when it is the k-th step
    of some key's procedure (behind a menu); large when no procedure sets it."""
    depths = [
        index
        for steps in model.features.values()
        for index, step in enumerate(steps)
        if step.variable == name
    ]
    return min(depths, default=FAR)


def _names_of(view: Model, name: str) -> tuple[str, ...]:
    """The ways the manual may print the setting: its label, its name in words."""
    info = view.infos.get(name)
    label = (info.var.label or "") if info is not None else ""
    found = {name.replace("_", " ").casefold()}
    if label.strip():
        found.add(label.strip().casefold())
    return tuple(sorted(found))


def _distance(lines: tuple[str, ...], names: tuple[str, ...], value: str) -> int:
    """The fewest lines between a line printing ``value`` and one printing any of ``names``."""
    at_value = _lines_with(lines, value.casefold())
    at_name = [k for n in names for k in _lines_with(lines, n)]
    if not at_value or not at_name:
        return FAR
    return min(abs(a - b) for a in at_value for b in at_name)


@lru_cache(maxsize=4096)
def _pattern(phrase: str) -> re.Pattern[str]:
    return re.compile(rf"(?<![a-z0-9]){re.escape(phrase)}(?![a-z0-9])")


def _lines_with(lines: tuple[str, ...], phrase: str) -> list[int]:
    if not phrase.strip():
        return []
    pattern = _pattern(phrase)
    return [k for k, line in enumerate(lines) if pattern.search(line)]
