"""A lamp-shown setting read from its lamp being dark only once that lamp was seen lit.

The belief's lamp words are the reader's guess ("BOOST" for boost on); the real panel may print
others ("MAX"/"STD"). Read against the guess, every display leaves the lamp dark, so the
setting reads as its unlit value on every screen — evidence made of nothing, on which the end
check would claim a goal such as boost=off without a single press. A dark lamp says something
only about a lamp the display has shown lit at some point in the episode (its words are the
panel's); until then the setting's value is unknown, so the loop looks (presses to see what
lights) instead of claiming.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from typing import Any

from apbot.model.display import lamp_for
from apbot.model.schema import ApplianceModel

__all__ = ["lit_lamps", "unproven_dark"]


def lit_lamps(
    model: ApplianceModel, text: str, domain: Callable[[str], tuple[Any, ...]]
) -> set[str]:
    """The indicators some lamp text of which shows, as whole words, in ``text``."""
    found = set()
    for name in model.display.indicators:
        spec = model.variables.get(name)
        if spec is None:
            continue
        values = domain(name)
        for value in values:
            lamp = lamp_for(spec, name, value, values)
            if lamp and re.search(rf"(?<!\w){re.escape(lamp)}(?!\w)", text, re.IGNORECASE):
                found.add(name)
                break
    return found


def unproven_dark(
    model: ApplianceModel,
    values: Mapping[str, Any],
    lit: set[str],
    domain: Callable[[str], tuple[Any, ...]],
) -> set[str]:
    """The indicators in ``values`` read as a value whose lamp is dark, while some other value
    of theirs lights a lamp never seen lit: the reading rests on the absence of a guessed word.
    Not a setting some screen prints by value (its reading is the print, not the lamp)."""
    printed = [model.display.idle, *(g.display or "" for g in model.guards)]
    for var in model.variables.values():
        show = var.show
        printed += list(show.values()) if isinstance(show, dict) else [show or ""]
    dark = set()
    for name, value in values.items():
        spec = model.variables.get(name)
        if name in lit or name not in model.display.indicators or spec is None:
            continue
        if any("{" + name + "}" in text for text in printed):
            continue
        options = domain(name)
        if lamp_for(spec, name, value, options):
            continue
        if any(lamp_for(spec, name, other, options) for other in options if other != value):
            dark.add(name)
    return dark
