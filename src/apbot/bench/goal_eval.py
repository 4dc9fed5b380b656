"""How well the offline goal parser reads a suite's instructions, given the true models.

A task counts as read only when the parsed goal equals the stored goal exactly after
normalisation: every variable, every value, nothing extra. Misses are listed with both goals
so that a reader sees what went wrong.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from fnmatch import fnmatchcase
from typing import Any

from apbot.bench.suite import Suite
from apbot.model.goal import parse_goal
from apbot.read.goal import GoalParseError, parse_instruction


@dataclass
class GoalMiss:
    appliance: str
    task: str
    instruction: str
    expected: dict[str, Any]
    parsed: dict[str, Any] | None
    error: str = ""


@dataclass
class GoalScore:
    """Exact-match counts, overall and per category, and the misses."""

    n: int = 0
    right: int = 0
    categories: dict[str, list[int]] = field(default_factory=dict)  # category -> [right, n]
    misses: list[GoalMiss] = field(default_factory=list)

    @property
    def accuracy(self) -> float:
        return self.right / self.n if self.n else 0.0

    def as_json(self) -> dict[str, Any]:
        return {
            "overall": {"accuracy": round(self.accuracy, 4), "n": self.n},
            "categories": {
                name: {"accuracy": round(r / n, 4) if n else 0.0, "n": n}
                for name, (r, n) in sorted(self.categories.items())
            },
            "misses": [miss.__dict__ for miss in self.misses],
        }


Parser = Callable[[Any, str, str], dict[str, Any]]  # (model, instruction, manual)


def evaluate_goals(
    suite: Suite,
    categories: list[str] | None = None,
    appliances: list[str] | None = None,
    parser: Parser | None = None,
    sample: int | None = None,
) -> GoalScore:
    """Parse every instruction of the chosen appliances and compare with the stored goal.

    ``appliances`` are ids or shell patterns (``"*_4"``); ``categories`` are category names;
    ``parser`` reads (model, instruction, manual) into a goal (default: the offline parser; it
    raises ``GoalParseError`` or another ``ValueError`` for an instruction it cannot read);
    ``sample``: only the first N tasks of each appliance.
    """
    score = GoalScore()
    for appliance in suite.appliances:
        category = appliance.category
        if categories and category not in categories:
            continue
        if appliances and not any(fnmatchcase(appliance.id, p) for p in appliances):
            continue
        for task in appliance.tasks[:sample]:
            expected = parse_goal(appliance.model, task.goal)
            parsed: dict[str, Any] | None
            error = ""
            try:
                if parser is not None:
                    parsed = parser(appliance.model, task.instruction, appliance.manual)
                else:
                    parsed = parse_instruction(appliance.model, task.instruction, appliance.manual)
            except (GoalParseError, ValueError) as exc:
                parsed, error = None, str(exc)
            ok = parsed == expected
            counts = score.categories.setdefault(category, [0, 0])
            counts[1] += 1
            score.n += 1
            if ok:
                counts[0] += 1
                score.right += 1
            else:
                score.misses.append(
                    GoalMiss(appliance.id, task.id, task.instruction, expected, parsed, error)
                )
    return score
