"""The bundled suite: complete, valid, reachable, and as varied as the issue asks."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from apbot.bench.oracle import run_suite_oracle
from apbot.bench.stats import suite_statistics
from apbot.bench.suite import CATEGORIES, GOAL_VARIABLES, bundled_suite_dir, load_suite
from apbot.bench.suite_check import check_appliance
from apbot.cli import app

SUITE = load_suite()
IDS = [a.id for a in SUITE.appliances]


def test_nine_categories_of_five_with_ten_tasks_each() -> None:
    assert len(SUITE.appliances) == 45 and len(SUITE.tasks) == 450
    for category in CATEGORIES:
        members = [a for a in SUITE.appliances if a.category == category]
        assert len(members) == 5, category
        assert all(len(a.tasks) == 10 for a in members)
        assert all(len(t.goal) == GOAL_VARIABLES[category] for a in members for t in a.tasks)


@pytest.mark.parametrize("appliance_id", IDS)
def test_appliance_passes_every_check(appliance_id: str) -> None:
    appliance = SUITE.get(appliance_id)
    errors = [p.render() for p in check_appliance(appliance) if p.severity == "error"]
    assert errors == []


def test_the_oracle_reaches_every_goal() -> None:
    results = run_suite_oracle(SUITE)
    failed = [(r.appliance, r.task, r.error) for r in results if not r.success]
    assert failed == []
    stored = {(a.id, t.id): t.optimal_steps for a, t in SUITE.tasks}
    assert all(stored[(r.appliance, r.task)] == r.actions for r in results)


def test_feature_quotas() -> None:
    features = suite_statistics(SUITE)["features"]
    assert features["keypad"] >= 8 and features["dial"] >= 8
    assert features["hold"] >= 10 and features["dependent_settings"] >= 6
    assert features["piecewise"] >= 10 and features["guards"] >= 10


def test_manuals_vary_in_length_and_form() -> None:
    words = sorted(a.manual_words for a in SUITE.appliances)
    assert words[0] >= 600 and words[-1] <= 3000
    assert words[-1] - words[0] > 1200
    assert sum(a.manual_file == "manual.txt" for a in SUITE.appliances) >= 9
    brands = {a.model.appliance.name.split()[0] for a in SUITE.appliances}
    assert len(brands) >= 40


def test_stats_json_shape() -> None:
    result = CliRunner().invoke(app, ["suite", "stats", "--json"])
    assert result.exit_code == 0, result.output
    stats = json.loads(result.output)
    assert stats["appliances"] == 45 and stats["tasks"] == 450
    assert set(stats["features"]) >= {
        "keypad",
        "dial",
        "hold",
        "two_control_hold",
        "dependent_settings",
        "piecewise",
        "guards",
    }
    for row in stats["categories"].values():
        assert {"appliances", "tasks", "goal_vars_per_task"} <= set(row)


def test_suite_ships_as_package_data() -> None:
    assert bundled_suite_dir().is_dir()
    assert sorted(p.name for p in bundled_suite_dir().iterdir() if p.is_dir()) == sorted(IDS)
