"""SPL by task index, with and without ``--learn`` (an agent that keeps its repairs).

    python benchmarks/learn_spl.py [--method apbot] [--belief read] [--goal read]
                                   [--categories a,b] [--workers 2] [--out runs/learn]

Runs the method over every appliance's tasks twice — each task from the run's belief, and with
``--learn`` each task from the belief the one before it left — and prints, per task index
(1 = an appliance's first task), SR and SPL of both runs, then the first and last tasks'
averages. Run directories are kept under ``--out`` (``plain/`` and ``learn/``), so a second call
resumes instead of starting over.
"""

from __future__ import annotations

import argparse
from collections import defaultdict
from pathlib import Path

from apbot.bench.records import TaskRecord
from apbot.bench.runner import BenchOptions, cached_suite, run_benchmark


def _by_index(records: list[TaskRecord]) -> dict[int, list[TaskRecord]]:
    suite = cached_suite("bundled")
    order = {(a.id, t.id): i + 1 for a in suite.appliances for i, t in enumerate(a.tasks)}
    out: dict[int, list[TaskRecord]] = defaultdict(list)
    for record in records:
        out[order[(record.appliance, record.task)]].append(record)
    return out


def _mean(values: list[float]) -> float:
    return sum(values) / len(values) if values else 0.0


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--method", default="apbot")
    parser.add_argument("--belief", default="read")
    parser.add_argument("--goal", default="read")
    parser.add_argument("--categories", default=None)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--out", default="runs/learn")
    args = parser.parse_args()
    runs = {}
    for name, learn in (("plain", False), ("learn", True)):
        outcome = run_benchmark(
            BenchOptions(
                methods=[args.method],
                categories=args.categories.split(",") if args.categories else None,
                workers=args.workers,
                out=Path(args.out) / name,
                belief=args.belief,
                goal=args.goal,
                learn=learn,
            ),
            progress=False,
        )
        runs[name] = _by_index(outcome.records)
    print(f"{args.method}, belief {args.belief}, goal {args.goal}: SR / SPL by task index")
    print(f"{'task':>5} {'SR':>7} {'SPL':>7} {'SR learn':>9} {'SPL learn':>10} {'n':>5}")
    for index in sorted(runs["plain"]):
        plain, learnt = runs["plain"][index], runs["learn"][index]
        print(
            f"{index:>5} {_mean([r.success for r in plain]):>7.3f} "
            f"{_mean([r.spl for r in plain]):>7.3f} {_mean([r.success for r in learnt]):>9.3f} "
            f"{_mean([r.spl for r in learnt]):>10.3f} {len(plain):>5}"
        )
    indices = sorted(runs["plain"])
    for label, chosen in (("first 3", indices[:3]), ("last 3", indices[-3:])):
        plain = [r.spl for i in chosen for r in runs["plain"][i]]
        learnt = [r.spl for i in chosen for r in runs["learn"][i]]
        print(f"{label:>8}: SPL {_mean(plain):.3f} without, {_mean(learnt):.3f} with --learn")


if __name__ == "__main__":
    main()
