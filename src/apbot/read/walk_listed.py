"""A walked field whose values the manual prints as a list elsewhere: "Hold SET for 3 seconds.
The current size flashes, for example C 2155 mm." with "Press MODE to go to the next larger
size", and, by the chart, "The list steps in the order …: 1515, 1615, 1890, … 2288."

The steps that open the field give no range (the values are uneven: a chart's rows), but the
display's example is one of them. The field's values are then the printed run of numbers, in
ascending order, that holds that example — the run the pair steps through. The field is named
by the section that opens it ("5.2 Wheel size (circumference)": wheel size).
"""

from __future__ import annotations

import re
from typing import Any

from apbot.read.build import Builder
from apbot.read.held_guesses import drop_unused
from apbot.read.labels import words
from apbot.read.value_lists import find_list

# the display's example of the field: "for example C 2155 mm", "e.g. 2155"
_EXAMPLE = re.compile(r"\b(?:e\.g\.|for\s+example|such\s+as)\s+(?:[A-Za-z]{1,3}\s)?(\d{2,5})\b")
# what flashes on opening: "The current size flashes"
_FLASHES = re.compile(r"\b(?:the\s+)?(?:current\s+)?([a-z][a-z -]{1,20}?)\s+(?:flashes|blinks)\b")
_NUMBER = re.compile(r"^\s*\d{1,5}\s*$")
_SECTION_NUMBER = re.compile(r"^\s*(?:\d+(?:\.\d+)*\.?|[A-Z]\.)\s+")


def listed_field(b: Builder, opened: str, at: int) -> dict[str, Any] | None:
    """The field the opening step shows, its values the printed ascending run of numbers (four
    or more) that holds the display's example; None when no such run is printed."""
    example = _EXAMPLE.search(opened)
    flashes = _FLASHES.search(opened)
    if not example or not flashes:
        return None
    shown = example.group(1)
    runs: list[list[str]] = []
    for unit in b.manual.units:
        found = find_list(unit.text)
        if not found or len(found[0]) < 4 or not all(_NUMBER.match(v) for v in found[0]):
            continue
        values = [v.strip() for v in found[0]]
        numbers = [int(v) for v in values]
        if shown in values and numbers == sorted(set(numbers)) and values not in runs:
            runs.append(values)
    if len(runs) != 1:
        return None  # none, or two that disagree: not read
    return {"name": _name(b, at) or flashes.group(1).strip().replace(" ", "_"), "values": runs[0]}


def _name(b: Builder, at: int) -> str:
    """The section's name, less its number and a bracket ("5.2 Wheel size (circumference)")."""
    heading = re.sub(r"\([^)]*\)", " ", _SECTION_NUMBER.sub("", b.manual.units[at].heading or ""))
    said = words(heading)
    return "_".join(said) if 1 <= len(said) <= 3 else ""


def drop_guessed_pair(b: Builder, steps: list[dict[str, Any]]) -> None:
    """Drop the setting the walk's pair was guessed to step on its own (a range the manual never
    gave, "0–10"): the walk read from the steps is what the pair sets."""
    walked = [s for s in steps if isinstance(s.get("effect"), dict)]
    if len(walked) != 1:
        return
    pair = set(walked[0]["effect"])
    read = {n.subject.split(".")[1] for n in b.notes if not n.guess and n.subject.count(".") >= 1}
    for fname, old in list(b.features.items()):
        if old is steps or len(old) != 1 or not isinstance(old[0].get("effect"), dict):
            continue
        var = str(old[0].get("variable"))
        if set(old[0]["effect"]) != pair or var in read or var not in b.variables:
            continue
        if b.variables[var].get("type") != "numeric":
            continue
        del b.features[fname]
        drop_unused(b, var)
