"""The number a keypad types when a confirm key names it ("OK  Ends the entry of a stitch
number"): the setting is that noun, a whole number, and its range is the numbers of the chart
keyed by it ("No. | Stitch | Use", rows 01 … 30) — not a cooking time in minutes and seconds."""

from __future__ import annotations

import re

from apbot.read.actions import ActionInfo
from apbot.read.build import Builder
from apbot.read.labels import words
from apbot.read.roles_confirm import KEYPAD_RE, confirmed_noun
from apbot.read.values import find_ranges

# the head of a chart's number column: "No.", "Nr", "#", "Number"
_NUMBER_HEAD_RE = re.compile(r"^\W*(?:no|nr|n°|number|num)\.?\W*$|^\W*#\W*$", re.I)


def _same_noun(text: str, noun: str) -> bool:
    """Whether a cell or line names the noun (a plural or a longer form of it counts)."""
    return any(w[:5] == noun[:5] and len(w) >= len(noun) - 1 for w in words(text))


def chart_numbers(b: Builder, noun: str) -> tuple[int, int, int] | None:
    """The lowest and highest number of a chart keyed by number whose name column (or the
    caption right above it) names the noun, and the unit index of its header."""
    units = b.manual.units
    for i, unit in enumerate(units):
        cells = unit.cells
        if not cells or unit.header or len(cells) < 2 or not _NUMBER_HEAD_RE.match(cells[0]):
            continue
        caption = units[i - 1].text if i > 0 and not units[i - 1].cells else ""
        if not (_same_noun(cells[1], noun) or _same_noun(caption, noun)):
            continue
        numbers = [
            int(u.cells[0].strip(" .)"))
            for u in units[i + 1 :]
            if u.header == cells and u.cells and u.cells[0].strip(" .)").isdigit()
        ]
        if len(numbers) >= 3:
            return min(numbers), max(numbers), i
    return None


def said_numbers(b: Builder, noun: str) -> tuple[int, int, int] | None:
    """A range without unit in a sentence naming the noun ("type 01 to 30 for the stitch"):
    the first one the manual gives."""
    for i, unit in enumerate(b.manual.units):
        if unit.cells or not _same_noun(unit.text, noun):
            continue
        for r in find_ranges(unit.text):
            if (r.low, r.high) == (0, 9) and KEYPAD_RE.search(unit.text):
                continue  # "Number keys 0-9 and OK - motif number": the keys, not the range
            if not r.unit and r.low >= 0 and r.high > r.low and float(r.low).is_integer():
                return int(r.low), int(r.high), i
    return None


def numbered_entry(b: Builder, digits: list[str], silent: list[ActionInfo]) -> ActionInfo | None:
    """When a key left without a role confirms "a <noun> number" and the manual numbers the
    noun (a chart keyed by number, or a range beside it), the number keys type that number and
    the key ends the entry; returns the key (None: no such key)."""
    for key in silent:
        noun = confirmed_noun(b, key)
        if not noun or key.skill != "press":
            continue
        found = chart_numbers(b, noun) or said_numbers(b, noun)
        if found is None:
            continue
        low, high, at = found
        name = b.unique(noun, b.variables)
        b.variables[name] = {
            "label": noun.upper(),
            "type": "numeric",
            "ranges": [[low, high, 1]],
            "entry": {"format": "number", "max_digits": len(str(high))},
        }
        b.note(f"variables.{name}", f"range {low}–{high}: the {noun} numbers", at)
        effect: dict[str, str] = {d: "digit" for d in digits}
        effect[key.name] = "none"
        b.feature(
            f"select_{name}",
            [{"actions": [*digits, key.name], "variable": name, "effect": effect}],
        )
        b.note(
            f"features.select_{name}", f"the number keys type the {noun}, {key.name} ends it", at
        )
        return key
    return None
