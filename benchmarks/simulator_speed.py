"""Simulator throughput: steps per second on random actions, per example model.

    python benchmarks/simulator_speed.py [--steps 200000]

Measures ``Simulator.step`` (names resolved, observation with display text built) and the raw
``CompiledModel.apply`` the planner uses.
"""

from __future__ import annotations

import argparse
import random
import time

from apbot.examples import example_names, load_example
from apbot.sim.simulator import Simulator


def measure(name: str, steps: int) -> tuple[float, float, float]:
    simulator = Simulator(load_example(name))
    rng = random.Random(0)
    actions = [rng.randrange(len(simulator.actions)) for _ in range(steps)]
    accepted = 0
    started = time.perf_counter()
    for action in actions:
        accepted += simulator.step(action).accepted
    step_rate = steps / (time.perf_counter() - started)
    compiled = simulator.compiled
    state = compiled.initial_state()
    started = time.perf_counter()
    for action in actions:
        state = compiled.apply(state, action) or state
    apply_rate = steps / (time.perf_counter() - started)
    return step_rate, apply_rate, accepted / steps


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--steps", type=int, default=200_000)
    args = parser.parse_args()
    print(f"{'model':<20} {'Simulator.step/s':>17} {'apply/s':>12} {'accepted':>9}")
    rates = []
    for name in example_names():
        step_rate, apply_rate, accepted = measure(name, args.steps)
        rates.append(step_rate)
        print(f"{name:<20} {step_rate:>17,.0f} {apply_rate:>12,.0f} {accepted:>9.0%}")
    print(f"slowest Simulator.step: {min(rates):,.0f} steps/s (target >= 100,000)")


if __name__ == "__main__":
    main()
