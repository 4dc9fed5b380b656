"""Check every stored ``optimal_steps`` of a suite against brute-force BFS.

    python benchmarks/optimal_counts.py [--max-states 50000] [--suite bundled]
                                        [--appliances ID,ID] [--verbose]

SPL divides by the ``optimal_steps`` stored in each task's ``tasks.yaml`` (the planner's answer
on the ground truth, written by ``apbot suite fill-optimal``). This re-derives each one by
breadth-first search over the whole simulator from the initial state — no planner involved —
wherever BFS fits ``--max-states`` states, and prints every mismatch and one summary line:

    optimal counts: 450 tasks, 431 checked by BFS (19 over budget), 431 confirmed, 0 mismatches

Exit status 1 when any checked count is wrong. Re-run it whenever goals or models change.
"""

from __future__ import annotations

import argparse
import sys
import time

from apbot.bench.suite import load_suite
from apbot.testing.bfs import OptimalCount, check_optimal_count, optimal_counts_line

DEFAULT_STATES = 50_000  # the whole bundled suite in under 2 minutes


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--max-states", type=int, default=DEFAULT_STATES)
    parser.add_argument("--suite", default="bundled", help="'bundled' or a suite directory")
    parser.add_argument("--appliances", help="comma-separated appliance ids (default: all)")
    parser.add_argument("--verbose", action="store_true", help="one line per task")
    args = parser.parse_args()
    suite = load_suite(args.suite)
    wanted = {a.strip() for a in args.appliances.split(",")} if args.appliances else None
    unknown = sorted((wanted or set()) - {a.id for a in suite.appliances})
    if unknown:
        sys.exit(f"error: no appliance {', '.join(unknown)} in suite {args.suite!r}")
    started = time.perf_counter()
    checks: list[OptimalCount] = []
    for appliance, task in suite.tasks:
        if wanted is not None and appliance.id not in wanted:
            continue
        began = time.perf_counter()
        check = check_optimal_count(appliance.model, task.goal, task.optimal_steps, args.max_states)
        checks.append(check)
        where = f"{appliance.id} {task.id} ({appliance.directory / 'tasks.yaml'})"
        if check.mismatch:
            found = "unreachable" if check.shortest is None else check.shortest
            print(f"MISMATCH {where}: stored {task.optimal_steps}, BFS {found}")
        elif args.verbose:
            verdict = "over budget" if check.over_budget else f"BFS {check.shortest}"
            print(
                f"{appliance.id} {task.id}: stored {task.optimal_steps}, {verdict}, "
                f"{check.states} states, {time.perf_counter() - began:.2f} s"
            )
    print(optimal_counts_line(checks))
    print(
        f"(BFS budget {args.max_states:,} states per task; {time.perf_counter() - started:.0f} s)"
    )
    if any(c.mismatch for c in checks):
        sys.exit(1)


if __name__ == "__main__":
    main()
