"""Planning time over all goals of the example models.

    python benchmarks/planning_time.py [--multi 300] [--values 40]

Goals: every variable with every value (at most ``--values`` evenly spread values for large
domains; dependent settings with their programme), plus ``--multi`` random goals of 2 to 6
variables per model built from random reachable states, plus the 6-variable washing-machine
goal the issue names. Times are from the initial state, after one warm-up plan per model (the
per-model lower-bound tables are cached, as they are in a running agent).
"""

from __future__ import annotations

import argparse
import random
import statistics
import time
from typing import Any

from apbot.examples import example_names, load_example
from apbot.model.domain import build_domain
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import Unreachable, plan
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import random_walk

WASHER_GOAL = {
    "power": "on",
    "programme": "wool",
    "temperature": "20",
    "spin_speed": "600 rpm",
    "finish_in": "5 h",
    "running": "on",
}


def single_goals(model: ApplianceModel, per_variable: int) -> list[dict[str, Any]]:
    goals = []
    for name, var in model.variables.items():
        if var.depends_on is None:
            values = list(build_domain(var).values)
            stride = max(1, len(values) // per_variable)
            goals += [{name: v} for v in values[::stride]]
        else:
            for case, spec in (var.cases or {}).items():
                goals += [{var.depends_on: case, name: v} for v in build_domain(var, spec).values]
    return goals


def multi_goals(model: ApplianceModel, count: int, rng: random.Random) -> list[dict[str, Any]]:
    compiled = compiled_model(model)
    goals = []
    names = list(model.variables)
    for _ in range(count):
        state = random_walk(compiled, rng, rng.randint(10, 80))
        chosen = rng.sample(names, min(len(names), rng.randint(2, 6)))
        goal = {n: compiled.value(state, n) for n in chosen}
        goal = {k: v for k, v in goal.items() if v is not None}
        for name in list(goal):
            parent = model.variables[name].depends_on
            if parent is not None:
                goal[parent] = compiled.value(state, parent)
        goals.append(goal)
    return goals


def timed(model: ApplianceModel, goal: dict[str, Any]) -> tuple[float, int | None]:
    started = time.perf_counter()
    try:
        length: int | None = len(plan(model, None, goal))
    except Unreachable:
        length = None
    return (time.perf_counter() - started) * 1000, length


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--multi", type=int, default=300)
    parser.add_argument("--values", type=int, default=40)
    args = parser.parse_args()
    rng = random.Random(0)
    print(
        f"{'model':<20} {'goals':>6} {'median ms':>10} {'p95 ms':>8} {'worst ms':>9} "
        f"{'unreachable':>11}"
    )
    everything = []
    for name in example_names():
        model = load_example(name)
        goals = single_goals(model, args.values) + multi_goals(model, args.multi, rng)
        timed(model, goals[0])  # warm-up: compile and cache lower bounds
        results = [timed(model, g) for g in goals]
        times = sorted(t for t, _ in results)
        everything += times
        print(
            f"{name:<20} {len(goals):>6} {statistics.median(times):>10.2f} "
            f"{times[int(0.95 * len(times))]:>8.2f} {times[-1]:>9.1f} "
            f"{sum(length is None for _, length in results):>11}"
        )
    print(
        f"all goals: {len(everything)}, median {statistics.median(everything):.2f} ms, "
        f"worst {max(everything):.1f} ms"
    )
    washer = load_example("washing_machine")
    times = sorted(timed(washer, WASHER_GOAL)[0] for _ in range(50))
    print(
        f"6-variable washing-machine goal: median {statistics.median(times):.2f} ms over 50 "
        f"runs (target < 50 ms); plan length {len(plan(washer, None, WASHER_GOAL))}"
    )


if __name__ == "__main__":
    main()
