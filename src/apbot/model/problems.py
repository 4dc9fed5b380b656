"""Problems found in a model: where (a path into the model, and a line when known) and what to do.

Both schema errors (pydantic) and semantic checks end up as :class:`Problem` objects, so a CLI,
a test or an LLM re-ask loop can show them the same way.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Literal

Severity = Literal["error", "warning"]
MORE = "… and "
"""How the line counting problems not shown begins (it sorts after the ones shown)."""
PathPart = str | int


_PLAIN_KEY = re.compile(r"[\w \-+/%°().']{1,80}")


def format_path(parts: Sequence[PathPart]) -> str:
    """``("features", "set_delay", 1, "actions")`` -> ``features.set_delay[1].actions``.

    A key a reader could not see or copy (empty, a line break, a control character, very
    long) is shown quoted, ``guards[0].when['\\n']``, so a problem always fits on one line.
    """
    text = ""
    for part in parts:
        if isinstance(part, int):
            text += f"[{part}]"
        elif not _PLAIN_KEY.fullmatch(str(part)) or str(part).strip() != str(part):
            shown = str(part) if len(str(part)) <= 80 else str(part)[:77] + "…"
            text += f"[{shown!r}]"
        else:
            text += f".{part}" if text else str(part)
    return text or "(model)"


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a model. ``check`` names the rule that found it.

    ``source`` is the file the problem is in, when the problem itself knows it (a suite's
    problems come from many files); otherwise the caller says which file it was reading.
    """

    path: tuple[PathPart, ...]
    message: str
    check: str
    severity: Severity = "error"
    line: int | None = None
    source: str | None = None

    @property
    def where(self) -> str:
        return format_path(self.path)

    def render(self, source: str | None = None) -> str:
        """One line: ``file:line: path: message [check]``."""
        location = self.source or source or ""
        if self.line is not None:
            location = f"{location}:{self.line}" if location else f"line {self.line}"
        prefix = f"{location}: " if location else ""
        where = f"{self.where}: " if self.path else ""  # a whole-file problem has no path
        return f"{prefix}{self.severity}: {where}{self.message} [{self.check}]"


class ModelError(ValueError):
    """A model that cannot be used; carries every problem found, errors first."""

    def __init__(self, problems: Iterable[Problem], source: str | None = None) -> None:
        self.problems = sorted(
            problems,
            key=lambda p: (p.severity != "error", p.message.startswith(MORE), p.line or 0),
        )
        self.source = source
        super().__init__(self.render())

    def render(self) -> str:
        errors = [p for p in self.problems if p.severity == "error"]
        head = f"{len(errors)} error(s) in {self.source or 'the model'}"
        return "\n".join([head, *(f"  {p.render(self.source)}" for p in self.problems)])
