"""A count said with "times" ("ten times over", "repeat it 3 times") is no TIME value: the
word "times" right after a number counts repeats, so a value match on it (a watch's TIME mode)
is dropped before the goal is read.
"""

from __future__ import annotations

from typing import Any

from apbot.model.values import words_to_number
from apbot.read.goal_text import Text


def counted_times(text: Text, matches: list[Any]) -> list[Any]:
    """The value matches, less those on "times" after a number."""

    def counted(match: Any) -> bool:
        if match.end - match.start != 1 or text.word(match.start) != "times":
            return False
        before = text.word(match.start - 1)
        return before[:1].isdigit() or words_to_number(before) is not None

    return [m for m in matches if not counted(m)]
