"""The brute-force reference: true distances, the exact projection, the budget, and the
stored-optimal-count check the lead re-runs after goals change."""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from apbot.bench.suite import load_suite
from apbot.model.goal import parse_goal
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import (
    BfsBudgetExceeded,
    OptimalCount,
    bound_violations,
    check_optimal_count,
    distances_to_goal,
    optimal_counts_line,
    planner_mismatches,
    random_walk,
    shortest_plan_length,
)
from apbot.testing.generate import random_goal, random_model
from tests.helpers import model_from

LEVEL = """
controls: [{id: up}, {id: down}, {id: other}]
variables:
  level: {type: numeric, ranges: [[0, 4, 1]]}
  other: {type: discrete, values: [a, b]}
actions: {press_up: {control: up}, press_down: {control: down}, press_other: {control: other}}
features:
  level: [{actions: [press_up, press_down], variable: level,
           effect: {press_up: next, press_down: prev}}]
  other: [{actions: [press_other], variable: other, effect: toggle}]
"""


def test_distances_from_every_state() -> None:
    model = model_from(LEVEL)
    compiled = compiled_model(model)
    states, distance = distances_to_goal(compiled, {"level": 3})
    # level 0..4 x other a/b x pointer (none, level step, other step), as reachable
    by_level = {compiled.value(s, "level"): distance[s] for s in states}
    assert by_level == {0: 3, 1: 2, 2: 1, 3: 0, 4: 1}
    assert len(distance) == len(states)  # the goal is reachable from everywhere


def test_budget_is_an_error_not_an_answer() -> None:
    compiled = compiled_model(model_from(LEVEL))
    with pytest.raises(BfsBudgetExceeded):
        distances_to_goal(compiled, {"level": 3}, max_states=4)
    with pytest.raises(BfsBudgetExceeded):
        shortest_plan_length(compiled, compiled.initial_state(), {"level": 4}, max_states=3)


def test_the_checks_report_what_is_wrong() -> None:
    """Given distances that are too short, both checks name the states that disagree."""
    model = model_from(LEVEL)
    compiled = compiled_model(model)
    states, _ = distances_to_goal(compiled, {"level": 3})
    zero = dict.fromkeys(states, 0)
    assert len(bound_violations(compiled, {"level": 3}, states, zero)) > 0
    wrong = planner_mismatches(compiled, {"level": 3}, [compiled.initial_state()], zero)
    assert wrong == [(compiled.initial_state(), 3, 0)]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(min_value=0, max_value=2**32 - 1))
def test_the_projection_keeps_every_distance(seed: int) -> None:
    """BFS over projected states (what the stored-count check uses) agrees with plain BFS."""
    rng = random.Random(seed)
    model = random_model(rng, max_states=3_000)
    goal = parse_goal(model, random_goal(rng, model))
    compiled = compiled_model(model)
    start = random_walk(compiled, rng, rng.choice([0, 5, 20]))
    plain = shortest_plan_length(compiled, start, goal, max_states=3_000)
    assert shortest_plan_length(compiled, start, goal, max_states=3_000, project=True) == plain


def test_stored_optimal_counts_of_a_sample_are_confirmed() -> None:
    """The first task of every bundled appliance: wherever BFS fits a small budget, the
    stored count (what SPL divides by) is the true optimum."""
    checks = []
    for appliance in load_suite().appliances:
        task = appliance.tasks[0]
        check = check_optimal_count(appliance.model, task.goal, task.optimal_steps, 3_000)
        assert not check.mismatch, f"{appliance.id} {task.id}: {check}"
        checks.append(check)
    assert sum(c.confirmed for c in checks) >= 10, optimal_counts_line(checks)


def test_a_wrong_stored_count_is_a_mismatch() -> None:
    model = model_from(LEVEL)
    assert check_optimal_count(model, {"level": 3}, 3, 1_000).confirmed
    assert check_optimal_count(model, {"level": 3}, 4, 1_000).mismatch
    assert check_optimal_count(model, {"level": 3}, None, 1_000).mismatch
    assert check_optimal_count(model, {"level": 4}, 4, 3).over_budget


def test_the_summary_line() -> None:
    checks = [
        OptimalCount(3, 3, False, 10),
        OptimalCount(4, 3, False, 10),
        OptimalCount(7, None, True, 100),
    ]
    assert optimal_counts_line(checks) == (
        "optimal counts: 3 tasks, 2 checked by BFS (1 over budget), 1 confirmed, 1 mismatches"
    )
