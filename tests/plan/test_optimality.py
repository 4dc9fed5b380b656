"""Property: on generated small models, the planner's plan is exactly as long as the shortest
sequence brute-force BFS finds over the whole simulator, from many start states, and
unreachable goals agree too.

The generator takes a seed, so hypothesis explores seeds; a failure names the seed, and
``random_model(random.Random(seed), MODEL_STATES)`` rebuilds the case. The generator never
draws a model with more states than BFS searches here, so every example is compared — none is
skipped. ``benchmarks/planner_optimality.py`` runs the same comparison over many more cases.
"""

from __future__ import annotations

import random

from hypothesis import HealthCheck, event, example, given, settings
from hypothesis import strategies as st

from apbot.model.goal import parse_goal
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import distances_to_goal, planner_mismatches, random_walk
from apbot.testing.generate import random_goal, random_model
from tests.plan.budget import OPTIMALITY, states_bucket

EXAMPLES, MODEL_STATES = OPTIMALITY
STARTS = 12  # start states per model: the initial one, random walks, random reachable ones


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(min_value=0, max_value=2**32 - 1))
# the family of ../shared/repro/planner_not_optimal.yaml (a dependent setting behind an entry
# press, its goal another programme's default): a bound adding the entry press to the
# programme route gave a longer plan here (3 of the first 2,500 seeds, with 5,000 states)
@example(seed=1523)
@example(seed=2059)
def test_planner_matches_breadth_first_search(seed: int) -> None:
    rng = random.Random(seed)
    model = random_model(rng, max_states=MODEL_STATES)
    goal = parse_goal(model, random_goal(rng, model))
    compiled = compiled_model(model)
    states, distance = distances_to_goal(compiled, goal, max_states=MODEL_STATES)
    picker = random.Random(f"{seed}/starts")
    walks = [random_walk(compiled, picker, picker.choice([3, 8, 20])) for _ in range(3)]
    others = picker.sample(states, min(len(states), STARTS - 1 - len(walks)))
    starts = [compiled.initial_state(), *walks, *others]
    event(states_bucket(len(states)))
    wrong = planner_mismatches(compiled, goal, starts, distance)
    assert wrong == [], f"seed {seed}: (start, planner, BFS) {wrong[:3]}, goal {goal}"
