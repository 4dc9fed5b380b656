"""Planner optimality against brute-force BFS on generated small models.

    python benchmarks/planner_optimality.py [--cases 1000] [--seed 0]

Each case: a random model (``apbot.model.generate``), a random goal, a start state reached by a
random walk; the planner's plan length is compared with BFS over the full simulator, and
unreachable goals must agree. Cases whose state space exceeds the BFS budget are skipped and
counted.
"""

from __future__ import annotations

import argparse
import random
import time

from apbot.model.generate import random_goal, random_model
from apbot.plan.bfs import compare_with_bfs, random_walk
from apbot.sim.compiled import compiled_model


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--cases", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--bfs-states", type=int, default=200_000)
    args = parser.parse_args()
    compared = mismatches = skipped = unreachable = 0
    lengths = []
    started = time.perf_counter()
    for seed in range(args.seed, args.seed + args.cases):
        rng = random.Random(seed)
        model = random_model(rng)
        goal = random_goal(rng, model)
        start = random_walk(compiled_model(model), rng, rng.choice([0, 0, 3, 8, 20]))
        try:
            found, shortest = compare_with_bfs(model, goal, start, args.bfs_states)
        except RuntimeError:
            skipped += 1
            continue
        compared += 1
        unreachable += shortest is None
        if shortest is not None:
            lengths.append(shortest)
        if found != shortest:
            mismatches += 1
            print(f"MISMATCH seed={seed}: planner {found}, BFS {shortest}, goal {goal}")
    seconds = time.perf_counter() - started
    print(
        f"compared {compared} (model, goal) cases, skipped {skipped} (BFS budget), {seconds:.1f} s"
    )
    print(
        f"mismatches: {mismatches}; unreachable goals (both agree): {unreachable}; "
        f"reachable plan lengths {min(lengths)}..{max(lengths)}, "
        f"mean {sum(lengths) / len(lengths):.1f}"
    )


if __name__ == "__main__":
    main()
