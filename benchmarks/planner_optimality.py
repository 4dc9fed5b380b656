"""Planner optimality and bound admissibility against brute-force BFS on generated small models.

    python benchmarks/planner_optimality.py [--cases 1000] [--seed 0] [--max-states 30000]
                                            [--starts 20]

Each case is a random model (``apbot.testing.generate``, at most ``--max-states`` states) and a
random goal. One breadth-first search forward from the initial state and one backward from the
goal states give the true distance from every reachable state. Then

* the planner plans from ``--starts`` of those states (the initial state and random others;
  0 = every reachable state), and each plan must be exactly as long as the distance
  (unreachable goals must agree);
* the planner's lower bound must not exceed the distance on any reachable state, and must be
  0 on goal states.

A case whose state space does not fit the BFS budget is counted, never silently dropped.
``--parts`` also prints, for every part of the format (``apbot.testing.generate.FORMAT_PARTS``),
how many compared cases used it and how many of those had a mismatch.
"""

from __future__ import annotations

import argparse
import random
import time
from collections import Counter

from apbot.model.goal import parse_goal
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import (
    BfsBudgetExceeded,
    bound_violations,
    distances_to_goal,
    planner_mismatches,
)
from apbot.testing.generate import FORMAT_PARTS, format_parts, random_goal, random_model

# parts of the format added for issue 12: cases using each are counted on their own
NEWER_PARTS = (
    "conditional effect",
    "one-position guard",
    "remembered setting",
    "skip",
    "timed cycle",
    "unreachable values",
)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--cases", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--max-states", type=int, default=30_000)
    parser.add_argument("--starts", type=int, default=20, help="0: every reachable state")
    parser.add_argument("--parts", action="store_true", help="cases and mismatches per part")
    args = parser.parse_args()
    part_cases: Counter[str] = Counter()
    part_wrong: Counter[str] = Counter()
    cases = too_large = starts_compared = states_checked = 0
    wrong_cases = unsound_cases = wrong_plans = unsound_states = unreachable = 0
    lengths: list[int] = []
    by_part = {part: [0, 0, 0] for part in NEWER_PARTS}  # cases, starts compared, mismatches
    started = time.perf_counter()
    for seed in range(args.seed, args.seed + args.cases):
        rng = random.Random(seed)
        model = random_model(rng, max_states=args.max_states)
        goal = parse_goal(model, random_goal(rng, model))
        compiled = compiled_model(model)
        try:
            states, distance = distances_to_goal(compiled, goal, max_states=args.max_states)
        except BfsBudgetExceeded:
            too_large += 1
            continue
        cases += 1
        parts = format_parts(model)
        part_cases.update(parts)
        picker = random.Random(f"{seed}/starts")
        starts = states if args.starts == 0 or args.starts >= len(states) else None
        if starts is None:
            starts = [states[0], *picker.sample(states[1:], args.starts - 1)]
        wrong = planner_mismatches(compiled, goal, starts, distance)
        unsound = bound_violations(compiled, goal, states, distance)
        for part in format_parts(model) & set(NEWER_PARTS):
            by_part[part][0] += 1
            by_part[part][1] += len(starts)
            by_part[part][2] += len(wrong)
        starts_compared += len(starts)
        states_checked += len(states)
        unreachable += sum(start not in distance for start in starts)
        lengths.extend(distance[start] for start in starts if start in distance)
        if wrong or unsound:
            part_wrong.update(parts)
        if wrong:
            wrong_cases += 1
            wrong_plans += len(wrong)
            state, found, shortest = wrong[0]
            print(
                f"MISMATCH seed={seed}: {len(wrong)}/{len(starts)} starts, e.g. planner {found}, "
                f"BFS {shortest} from {state}; goal {goal}"
            )
        if unsound:
            unsound_cases += 1
            unsound_states += len(unsound)
            state, estimate, truth = unsound[0]
            print(
                f"BOUND seed={seed}: {len(unsound)}/{len(states)} states, e.g. bound {estimate} "
                f"> distance {truth} at {state}; goal {goal}"
            )
    seconds = time.perf_counter() - started
    mean = sum(lengths) / len(lengths) if lengths else 0.0
    print(
        f"planner vs BFS: {cases} (model, goal) cases, {starts_compared} start states compared, "
        f"{wrong_plans} mismatches in {wrong_cases} cases, {too_large} cases over the BFS "
        f"budget; {unreachable} unreachable starts (both agree unless counted above); "
        f"plan lengths {min(lengths, default=0)}..{max(lengths, default=0)}, mean {mean:.1f}"
    )
    print(
        f"bound vs BFS distance: {states_checked} states of {cases} cases checked, "
        f"{unsound_states} where the bound is above the distance (or not 0 at a goal) "
        f"in {unsound_cases} cases; {seconds:.1f} s"
    )
    if args.parts:
        for part in FORMAT_PARTS:
            print(f"  {part}: {part_cases[part]} cases, {part_wrong[part]} with a mismatch")
    for part, (count, compared, mismatches) in by_part.items():
        print(f"  using {part}: {count} cases, {compared} starts compared, {mismatches} mismatches")


if __name__ == "__main__":
    main()
