"""A key's name printed as a value of another key's cycle: no sentence about that key.

A value can share its word with a key of the panel: a crust of LIGHT, MEDIUM or DARK beside a
LIGHT key for the lamp, a fan speed TURBO beside a TURBO key. The sentence giving the crust's
cycle after the CRUST key's line ("One touch: the next level, LIGHT → MEDIUM → DARK → LIGHT.")
then names the LIGHT key by the words alone, and read as a sentence about the lamp it would be
no evidence for the crust. Keys pressed one after another never come back round to the first;
the values a key steps through do. So a key's name that appears only as an item of a run of
arrows coming back round to its start is that run's value, not the key.
"""

from __future__ import annotations

import re

from apbot.read.shapes import CYCLE_ARROW, comes_round
from apbot.read.value_lists import find_list


def named_in_cycle_only(name: str, text: str) -> bool:
    """Whether ``text`` prints the key ``name`` only as a value of a cycle drawn in arrows."""
    if not name or not re.search(r"[A-Za-z]", name):
        return False
    found = find_list(text)
    if found is None or found[1] != "arrows" or not comes_round(found[0], text):
        return False
    if name.upper() not in {item.strip(" .").upper() for item in found[0]}:
        return False
    item = r"[A-Za-z0-9][\w+/ .'-]{0,20}?"
    run = re.search(rf"{item}(?:{CYCLE_ARROW}{item})+(?={CYCLE_ARROW}|[.,;)]|\s*$)", text)
    rest = text[: run.start()] + " " + text[run.end() :] if run else text
    printed = re.compile(rf"(?<![A-Za-z0-9]){re.escape(name)}(?![A-Za-z0-9])", re.IGNORECASE)
    return not printed.search(rest.replace("→", " "))
