"""Goals: a partial assignment of variables, normalised to canonical values.

Success is judged on the final state (as tau-bench compares the final database, not the
actions): every goal variable must hold its canonical goal value.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from apbot.model.domain import normalise
from apbot.model.problems import Problem
from apbot.model.schema import ApplianceModel
from apbot.model.validate import check_goal

Goal = dict[str, Any]


class GoalError(ValueError):
    """A goal that names unknown variables or impossible values."""

    def __init__(self, problems: list[Problem]) -> None:
        self.problems = problems
        super().__init__("; ".join(f"{p.where}: {p.message}" for p in problems))


def split_assignments(items: Iterable[str]) -> dict[str, str]:
    """``["power=on", "delay = 2 h"]`` -> ``{"power": "on", "delay": "2 h"}``."""
    goal: dict[str, str] = {}
    for item in items:
        if not isinstance(item, str):
            raise GoalError([Problem(("goal",), f"{item!r} is not NAME=VALUE text", "goal")])
        name, sep, value = item.partition("=")
        name = name.strip()
        if not sep or not name:
            raise GoalError([Problem(("goal",), f"{item!r} is not NAME=VALUE", "goal")])
        if name in goal and goal[name] != value.strip():
            raise GoalError(
                [
                    Problem(
                        ("goal", name),
                        f"given twice ({goal[name]!r} and {value.strip()!r}); say which one",
                        "goal",
                    )
                ]
            )
        goal[name] = value.strip()
    return goal


def parse_goal(model: ApplianceModel, goal: Mapping[str, Any] | Iterable[str]) -> Goal:
    """Validate and normalise a goal; raise :class:`GoalError` naming every bad entry.

    >>> from apbot.examples import load_example
    >>> parse_goal(load_example("washing_machine"), ["programme=Wool", "temperature=30 °C"])
    {'programme': 'wool', 'temperature': '30'}
    """
    raw = dict(goal) if isinstance(goal, Mapping) else split_assignments(goal)
    problems = check_goal(model, raw)
    if problems:
        raise GoalError(problems)
    return {name: normalise(model.variables[name], value) for name, value in raw.items()}
