"""The error the goal parser raises when an instruction asks for what the model cannot do."""

from __future__ import annotations

from typing import Any


class GoalParseError(ValueError):
    """The instruction asks for something the model cannot do.

    ``words`` quotes the instruction's words at fault; ``reason`` says why (no such value, out
    of range, and what the model offers instead).
    """

    def __init__(self, words: str, reason: str) -> None:
        self.words = words
        self.reason = reason
        self.setting: str | None = None  # the setting it would go to, when there is one
        self.asked: Any = None  # the value as said, in that setting's terms
        super().__init__(f"{words!r}: {reason}")
