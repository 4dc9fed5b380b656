"""End to end with no LLM: beliefs read from the manuals, goals read from the instructions.

    python benchmarks/end_to_end.py [--methods apbot,apbot-open-loop] [--workers 2]
                                    [--out runs/e2e] [--feedback display] [--sample N]
                                    [--categories a,b]

Runs ``apbot bench`` with its defaults (``--belief read --goal read``) and prints SR and SPL
per category and method, overall, on the six categories held back from the reader's and the
goal parser's development, and on the nine others; plus how many parsed goals are the stored
one. The run directory is kept, so a second call resumes (``--sample N``: the first N tasks of
each appliance; a later call without it completes the run).
"""

from __future__ import annotations

import argparse
from collections import defaultdict
from pathlib import Path

from apbot.bench.records import TaskRecord
from apbot.bench.runner import BenchOptions, run_benchmark
from apbot.bench.suite import HELD_OUT_CATEGORIES

HELD_BACK = HELD_OUT_CATEGORIES


def _figures(records: list[TaskRecord]) -> str:
    if not records:
        return "   –        –    "
    sr = sum(r.success for r in records) / len(records)
    spl = sum(r.spl for r in records) / len(records)
    return f"{sr:>6.3f} / {spl:<6.3f}"


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--methods", default="apbot,apbot-open-loop")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--out", default="runs/e2e")
    parser.add_argument("--feedback", default="display", choices=("display", "values"))
    parser.add_argument("--sample", type=int, default=None, help="first N tasks per appliance")
    parser.add_argument("--categories", default=None, help="comma-separated (default: all)")
    args = parser.parse_args()
    methods = args.methods.split(",")
    outcome = run_benchmark(
        BenchOptions(
            methods=methods,
            workers=args.workers,
            out=Path(args.out),
            feedback=args.feedback,  # type: ignore[arg-type]
            sample=args.sample,
            categories=args.categories.split(",") if args.categories else None,
        ),
        progress=False,
    )
    by: dict[tuple[str, str], list[TaskRecord]] = defaultdict(list)
    for record in outcome.records:
        by[record.method, record.category].append(record)
        by[record.method, "overall"].append(record)
        group = "six held back" if record.category in HELD_BACK else "nine others"
        by[record.method, group].append(record)
    categories = sorted({r.category for r in outcome.records})
    print(f"SR / SPL, belief read, goal read, {args.feedback} feedback")
    print(f"{'':<18}" + "".join(f"{m:>20}" for m in methods))
    for row in [*categories, "nine others", "six held back", "overall"]:
        print(f"{row:<18}" + "".join(f"{_figures(by[m, row]):>20}" for m in methods))
    parsed = [r for r in outcome.records if r.method == methods[0]]
    exact = sum(1 for r in parsed if r.goal_exact)
    print(f"goals read = the stored goal (under the alignment): {exact} of {len(parsed)}")


if __name__ == "__main__":
    main()
