"""The reading report: where every part of a read model came from, and every guess.

The closed loop repairs a wrong belief; the report says which parts of the belief rest on the
manual (with the line) and which the reader made up where the manual is silent, so a person or
the agent knows what to distrust first.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any


@dataclass(frozen=True)
class Note:
    """One finding: ``subject`` is a model path (``variables.fan_speed``), ``what`` says what was
    read or guessed, ``line``/``quote`` the manual line it came from (None for a guess)."""

    subject: str
    what: str
    line: int | None = None
    quote: str = ""
    guess: bool = False

    def render(self) -> str:
        where = f"line {self.line}: {self.quote!r}" if self.line else "no manual line"
        tag = "GUESS " if self.guess else ""
        return f"{tag}{self.subject}: {self.what} ({where})"


@dataclass
class Report:
    notes: list[Note]

    @property
    def guesses(self) -> list[Note]:
        return [n for n in self.notes if n.guess]

    def render(self) -> str:
        read = [n for n in self.notes if not n.guess]
        lines = [f"read from the manual ({len(read)}):"]
        lines += [f"  {n.render()}" for n in read]
        lines.append(f"guesses where the manual is silent ({len(self.guesses)}):")
        lines += [f"  {n.render()}" for n in self.guesses]
        return "\n".join(lines)

    def to_json(self) -> list[dict[str, Any]]:
        return [asdict(n) for n in self.notes]
