"""How long the full offline benchmark takes (every method a plain bench runs × every task).

    python benchmarks/bench_time.py [--workers 2] [--methods a,b] [--sample N] [--budget 120]
                                    [--warm]

Runs the defaults (beliefs read from the manuals, goals read from the instructions, display
feedback) into a fresh temporary directory (nothing is resumed) and times all of it: suite
load, reading the manuals (into an empty read cache, unless --warm uses the user's), worker
start-up, every task, the results file and summary.json. Prints the
wall time, tasks per second and each method's success rate; exits 1 when over ``--budget``
seconds (the target is under 2 minutes with 2 workers on a 2-core machine).
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

from apbot.agent.registry import default_methods
from apbot.bench.runner import BenchOptions, run_benchmark


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument(
        "--methods", default=None, help="comma-separated (default: every method needing no LLM)"
    )
    parser.add_argument("--sample", type=int, default=None, help="first N tasks per appliance")
    parser.add_argument("--budget", type=float, default=120.0, help="seconds allowed")
    parser.add_argument("--warm", action="store_true", help="use the user's read cache")
    args = parser.parse_args()
    chosen = args.methods.split(",") if args.methods else default_methods()
    with tempfile.TemporaryDirectory(prefix="apbot-bench-time-") as out:
        if not args.warm:
            os.environ["APBOT_CACHE_DIR"] = str(Path(out) / "cache")  # every manual read anew
        started = time.perf_counter()
        outcome = run_benchmark(
            BenchOptions(
                methods=chosen, sample=args.sample, workers=args.workers, out=Path(out) / "run"
            ),
            progress=False,
        )
        seconds = time.perf_counter() - started
    tasks = len(outcome.records)
    print(
        f"{tasks} tasks ({len(chosen)} methods) with {args.workers} worker(s): "
        f"{seconds:.1f} s, {tasks / seconds:.0f} tasks/s (budget {args.budget:g} s)"
    )
    for name, row in outcome.summary["methods"].items():
        overall = row["overall"]
        print(f"  {name:<24} SR {overall['sr']:.3f}  SPL {overall['spl']:.3f}  n {overall['n']}")
    if seconds > args.budget:
        sys.exit(f"over budget: {seconds:.1f} s > {args.budget:g} s")


if __name__ == "__main__":
    main()
