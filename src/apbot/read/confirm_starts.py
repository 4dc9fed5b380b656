"""A start that must be confirmed: "The first press only asks for confirmation (START? flashes).
Press START/STOP a second time." — a two-press start.

Appliances that heat oil, water or a blade guard their start this way: the first press shows a
request, the second starts, a third stops. Read as an on/off toggle, one press leaves the
appliance waiting on its request while the belief thinks it runs. The running variable is then
a cycle of three states, off → the request → on, stepped by the start key; the request's
display word is the capitalised word the sentence shows ("START?"), when it names one.
"""

from __future__ import annotations

import re

from apbot.read.build import Builder

# "two-press start", "asks you to confirm every start", "the first press only asks for
# confirmation", "the 1st press requests the start"
_CONFIRMED_START = re.compile(
    r"\b(?:two|2)[- ]press\s+start\b|\bconfirm\s+(?:every|each|the)\s+start\b|"
    r"\b(?:first|1st)\s+press\b[^.]{0,60}?\b(?:confirm\w*|request\w*)\b",
    re.IGNORECASE,
)
_STARTS = re.compile(r"\b(?:starts|begins|is\s+started)\b", re.IGNORECASE)
# a cell holding one display word ("FRY", "RUN", "P-1"): no key's label, no sentence
_WORD_CELL = re.compile(r"[A-Z][A-Z0-9-]{1,6}")


def read_confirmed_starts(b: Builder) -> None:
    """Make the running variable off → request → on when the manual says a start is
    confirmed by a second press of the start key."""
    said = [i for i, u in enumerate(b.manual.units) if _CONFIRMED_START.search(u.text)]
    if not said or "running" not in b.variables:
        return
    spec = b.variables["running"]
    if spec.get("values") != ["off", "on"]:
        return
    found = [
        (name, steps)
        for name, steps in b.features.items()
        if len(steps) == 1
        and steps[0].get("variable") == "running"
        and steps[0].get("effect") == "toggle"
        and len(steps[0].get("actions") or []) == 1
    ]
    if len(found) != 1:
        return  # one start key toggling: the key that is pressed twice
    spec["values"] = ["off", "confirm", "on"]
    found[0][1][0]["effect"] = "next"
    b.note("variables.running", "a first press asks for confirmation, a second starts", said[0])
    word, at = _started_word(b)
    if word:  # the press-by-press table's word: the belief can see the start take hold
        spec.pop("visible", None)
        spec["show"] = {"off": "", "on": word}
        b.note("variables.running.show", f"the panel shows {word} once it runs", at)
        request = _request_word(b, said)
        if request:  # "START? (flashing)": the request's own word
            spec["show"]["confirm"] = request


def _started_word(b: Builder) -> tuple[str, int | None]:
    """The display word of a table row whose other cell says the work starts ("START/STOP
    (2nd) | FRY | frying starts"): a press-by-press table of what the display shows."""
    keys = {lab.text.upper() for lab in b.labels.values() if lab.text}
    for i, unit in enumerate(b.manual.units):
        cells = [c.strip() for c in unit.cells]
        if len(cells) < 3 or not any(_STARTS.search(c) for c in cells):
            continue
        words = [c for c in cells if _WORD_CELL.fullmatch(c) and c.upper() not in keys]
        if len(words) == 1:
            return words[0], i
    return "", None


# the request's word: "START? (flashing)", "START? flashes", "CONF blinks"
_REQUEST = re.compile(r"(?<![\w?])([A-Z][A-Z0-9]{1,7}\??)\s*\(?\s*(?:flash|blink)")


def _request_word(b: Builder, said: list[int]) -> str:
    """The display word of the start request: in a sentence saying the start is confirmed,
    else in a table row of the first press ("START (1st) | READY? (flashing)")."""
    rows = [i for i, u in enumerate(b.manual.units) if u.cells and _FIRST.search(u.text)]
    for i in said + rows:
        m = _REQUEST.search(b.manual.units[i].text)
        if m:
            return m.group(1)
    return ""


_FIRST = re.compile(r"\b(?:1st|first)\b", re.IGNORECASE)
