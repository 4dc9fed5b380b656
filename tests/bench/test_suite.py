"""The bundled suite: complete, valid, reachable, and as varied as the issue asks."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from apbot.agent.environment import SimulatorEnvironment
from apbot.agent.episode import TaskContext
from apbot.agent.registry import get_method
from apbot.bench.oracle import oracle_plan, run_task
from apbot.bench.stats import suite_statistics
from apbot.bench.suite import (
    CATEGORIES,
    GOAL_VARIABLES,
    SuiteAppliance,
    Task,
    bundled_suite_dir,
    load_suite,
)
from apbot.bench.suite_check import check_appliance
from apbot.cli import app
from apbot.model.goal import parse_goal
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import shortest_plan_length

SUITE = load_suite()
IDS = [a.id for a in SUITE.appliances]


def test_fifteen_categories_of_five_with_ten_tasks_each() -> None:
    assert len(SUITE.appliances) == 75 and len(SUITE.tasks) == 750 and len(CATEGORIES) == 15
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


# Tasks of the larger categories whose full state space BFS can still search (ids only: the
# expected counts come from BFS); the sweep below covers every task small enough for it.
BFS_TASKS = [
    ("air_fryer_2", "t01"),
    ("air_fryer_2", "t05"),
    ("bread_maker_1", "t04"),
    ("bread_maker_2", "t07"),
    ("induction_cooker_1", "t07"),
    ("washing_machine_1", "t06"),
    ("washing_machine_2", "t10"),
    ("washing_machine_4", "t01"),
]


def _bfs_length(appliance: SuiteAppliance, task: Task, max_states: int) -> int | None:
    compiled = compiled_model(appliance.model)
    goal = parse_goal(appliance.model, task.goal)
    return shortest_plan_length(compiled, compiled.initial_state(), goal, max_states)


def test_stored_optimal_counts_equal_breadth_first_search() -> None:
    """The stored counts against brute force over the full simulator, not the planner."""
    compared = []
    for appliance, task in SUITE.tasks:
        try:
            shortest = _bfs_length(appliance, task, 600)
        except RuntimeError:
            continue  # too many states for a test; the planner's tests cover the method
        compared.append((appliance.id, task.id, task.optimal_steps, shortest))
    assert len(compared) >= 150
    assert [c for c in compared if c[2] != c[3]] == []


@pytest.mark.parametrize(("appliance_id", "task_id"), BFS_TASKS)
def test_stored_optimal_count_of_a_larger_task_equals_bfs(appliance_id: str, task_id: str) -> None:
    appliance = SUITE.get(appliance_id)
    task = next(t for t in appliance.tasks if t.id == task_id)
    assert task.optimal_steps == _bfs_length(appliance, task, 3000)


def test_the_oracle_method_presses_the_suite_oracles_plan() -> None:
    """One oracle: the benchmark method, the suite oracle and the checker share one plan."""
    for category in CATEGORIES:
        appliance = next(a for a in SUITE.appliances if a.category == category)
        task = appliance.tasks[-1]
        env = SimulatorEnvironment(appliance.model)
        context = TaskContext(
            appliance.id,
            appliance.category,
            task.id,
            task.instruction,
            dict(task.goal),
            appliance.model,
            actions=tuple(env.actions),
        )
        episode = get_method("oracle").run(context, env)
        pressed = [e.action for e in episode.trace if e.kind == "action"]
        _goal, found = oracle_plan(appliance.model, task.goal)
        assert pressed == [a.name for a in found.actions], appliance.id
        assert env.simulator.satisfies(parse_goal(appliance.model, task.goal))
        result = run_task(appliance, task)
        assert result.success and result.actions == len(pressed) == task.optimal_steps


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
    assert stats["appliances"] == 75 and stats["tasks"] == 750
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
