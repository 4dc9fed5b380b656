"""How a number in the instruction was said, for open goal entries (:mod:`apbot.read.goal_open`).

Which mentions are remarks rather than values to set (a tally, "in 10 minutes", "my kids are
5"), which words never name a setting, and the value written as a display would show it.
"""

from __future__ import annotations

import re
from typing import Any

from apbot.model.values import words_to_number
from apbot.read.goal_text import Text
from apbot.read.goal_vocab import stem
from apbot.read.numbers import Mention

NOT_LEVELS = frozenset(
    {"are", "is", "was", "were", "be", "been", "being", "aged", "age", "ages", "about",
     "around", "than", "them", "they", "we", "you", "my", "our", "your", "his", "her",
     "their", "those", "these", "back", "again", "times", "until", "till", "every", "each"}
)  # fmt: skip
"""Words that stand before a number without naming a setting ("my kids are 5")."""


NEVER_NAMES = frozenset(
    {"not", "no", "never", "nor", "without", "start", "stop", "pause", "cancel", "begin",
     "resume", "reset", "clear", "enter", "confirm", "ok"}
)  # fmt: skip
"""Words that name no setting, whichever way they were found: a negation ("not 30"), a key
that acts rather than holds a value ("start")."""

_TALLIES = frozenset({"times", "stars", "star", "points", "votes", "reviews", "ratings"})
"""Nouns after a number that count events or score something ("opened 20 times", "5 stars"):
a remark, never a value to set."""


def tally(text: Text, mention: Mention) -> bool:
    """The number counts events or rates ("20 times", "5 stars", "4 out of 5"), it sets
    nothing."""
    if mention.kind != "number":
        return False
    after = text.word(mention.end)
    noun = mention.unit.casefold() or after
    return noun in _TALLIES or (after == "out" and text.word(mention.end + 1) == "of")


_PER = frozenset({"a", "an", "per", "each", "every"})
_HOW_OFTEN = frozenset({"once", "twice", "thrice", "times"})


def per_period(text: Text, mention: Mention) -> bool:
    """ "three doses a day", "twice a day", "4 times per week": the period a count is made
    in, no length of time to set."""
    if mention.kind != "duration" or text.word(mention.start) not in _PER:
        return False
    before = text.word(mention.start - 1)
    if before in _HOW_OFTEN:
        return True
    counted = text.word(mention.start - 2)
    return (
        len(before) > 3
        and before.endswith("s")
        and (counted[:1].isdigit() or words_to_number(counted) is not None)
    )


def in_days(text: Text, mention: Mention) -> bool:
    """A duration said in days ("for 14 days"), not one that adds up to whole days ("48
    hours")."""
    return any(text.word(k).startswith("day") for k in range(mention.start, mention.end))


def remark(text: Text, mention: Mention) -> bool:
    """A time from now, not a setting: "I'll be back in 10 minutes" ("in" before a duration
    says when, not how long)."""
    return mention.kind == "duration" and text.word(mention.start - 1) == "in"


def counted_stems(manual: str) -> frozenset[str]:
    """The stems of the nouns a manual counts: the word after a number or a span of numbers
    ("1 – 4 cups", "up to 6 slices")."""
    found = re.findall(r"\d\s*(?:[-–]\s*\d+\s*)?([a-z]+)", manual.lower())
    return frozenset(stem(w) for w in found)


def manual_stems(manual: str) -> frozenset[str]:
    """The stems of the words a manual uses (empty without a manual)."""
    return frozenset(stem(w) for w in re.findall(r"[a-z]+", manual.lower()))


_BASE_UNITS = {"mass": "g", "volume": "ml", "power": "W"}


def as_said(text: Text, mention: Mention) -> Any:
    """The value as the user said it: a whole number as itself, a duration in its largest
    whole unit ("45 min", "2 h"), a weight, volume or power in grams, millilitres or watts
    ("1.25 kg" → "1250 g"), another quantity with the unit said."""
    if mention.kind == "number":
        number = mention.value
        return int(number) if float(number).is_integer() else number
    if mention.kind == "duration":
        seconds = round(mention.value)
        sizes = ((86400, "d"), (3600, "h"), (60, "min"))
        for size, unit in sizes if in_days(text, mention) else sizes[1:]:
            if seconds % size == 0 and seconds >= size:
                return f"{seconds // size} {unit}"
        return f"{seconds} s"
    base = _BASE_UNITS.get(mention.dimension or "")
    if mention.kind == "quantity" and base and float(mention.value).is_integer():
        return f"{int(mention.value)} {base}"  # "1.25 kg" as a display writes it: 1250 g
    if mention.kind == "quantity" and mention.unit:
        said = text.word(mention.start)
        try:
            float(said)
        except ValueError:
            return None  # "two kilos": no number written as the display writes it
        return f"{said} {mention.unit}"
    return None
