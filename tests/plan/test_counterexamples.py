"""Models that once fooled the planner (from code review): each plan must match BFS.

They exercise shapes the random generator rarely builds: a bound term counted twice, exits of
large domains pruned by a loose bound, guards on large numeric and keypad variables, a keypad
step that only shows its value on entry.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from apbot.model.load import load_model
from apbot.plan.bfs import compare_with_bfs

HERE = Path(__file__).parent / "counterexamples"

CASES = [
    ("ce_charge", {"v": "v1", "w": "w1"}),
    ("ce_useful", {"level": 57}),
    ("ce1", {"level": 57}),
    ("ce1", {"level": 99}),
    ("ce_guard_keypad", {"running": "on"}),
    ("ce_guard_keypad10", {"running": "on"}),
    ("ce_guard_big", {"running": "on"}),
    ("ce_show_keypad", {"minutes": 12}),
]


@pytest.mark.parametrize(("name", "goal"), CASES, ids=[f"{n}-{next(iter(g))}" for n, g in CASES])
def test_planner_matches_bfs(name: str, goal: dict[str, object]) -> None:
    model = load_model(HERE / f"{name}.yaml", check=False)
    found, shortest = compare_with_bfs(model, goal, max_states=2_000_000)
    assert found == shortest
