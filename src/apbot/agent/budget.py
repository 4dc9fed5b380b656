"""How often the closed loop may try each kind of repair: a typed budget of attempts.

Two kinds of limits, kept apart on purpose:

* **once only** — a probe whose answer cannot change by asking again (walk a setting the
  belief cannot reach, explain a refusal by a guard, probe the keys in front of an unreachable
  setting, try a key as a further step of a procedure). Spent for the whole episode: nothing
  that happens later makes them worth repeating.
* **in a row** — the same repair needed again and again (a setting that keeps showing values
  the model does not predict, a procedure that keeps failing). Counted per variable or
  feature, and forgiven for that variable or feature only once it works as predicted; the
  episode gives up when one of them comes back more than ``limit`` times.

>>> budget = Budget(limit=2)
>>> budget.once("inspect", "timer"), budget.once("inspect", "timer")
(True, False)
>>> budget.again("value", "timer"), budget.again("value", "timer"), budget.again("value", "timer")
(True, True, False)
>>> budget.works("value", ["timer"]); budget.again("value", "timer")
True
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Literal

OnceKind = Literal[
    "inspect",
    "guard",
    "unreachable",
    "absorbed",
    "entry",
    "template",
    "case",
    "discover",
    "side",
    "start",
    "end",
]
RepeatKind = Literal["value", "procedure", "display"]
MAX_SAME_REPAIR = 3  # the same thing going wrong this often in a row: give up


@dataclass
class Budget:
    """The attempts an episode has left (see the module docstring)."""

    limit: int = MAX_SAME_REPAIR
    spent: dict[OnceKind, set[str]] = field(default_factory=dict)
    streaks: dict[RepeatKind, Counter[str]] = field(default_factory=dict)

    def once(self, kind: OnceKind, key: str) -> bool:
        """True the first time ``(kind, key)`` is asked for, False ever after."""
        done = self.spent.setdefault(kind, set())
        if key in done:
            return False
        done.add(key)
        return True

    def spent_on(self, kind: OnceKind, key: str) -> bool:
        """``(kind, key)`` was asked for already (without asking now)."""
        return key in self.spent.get(kind, set())

    def again(self, kind: RepeatKind, key: str) -> bool:
        """Count one more occurrence; False once it has come back more than ``limit`` times."""
        streak = self.streaks.setdefault(kind, Counter())
        streak[key] += 1
        return streak[key] <= self.limit

    def works(self, kind: RepeatKind, keys: list[str] | set[str]) -> None:
        """These variables or features did what the belief predicted: forgive their streaks."""
        streak = self.streaks.get(kind)
        if streak is not None:
            for key in keys:
                streak.pop(key, None)
