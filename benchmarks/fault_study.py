"""Fault study: SR and SPL of the closed loop and the open loop as the belief gets more wrong.

    python benchmarks/fault_study.py --rates 0,0.1,0.2,0.3,0.5 --seeds 0,1,2 --out runs/faults
        [--methods apbot,apbot-open-loop] [--workers N] [--sample N] [--appliances a,b]

One benchmark per (rate, seed) in OUT/rate-R-seed-S/ (each resumable: run the same command
again after an interruption); OUT/fault_study.json holds the figures averaged over the seeds
and OUT/fault_study.png plots SR and SPL against the fault rate. Prints a table of the figures.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from rich.console import Console
from rich.table import Table

from apbot.bench.fault_study import (
    DEFAULT_METHODS,
    PLOT_FILE,
    STUDY_FILE,
    FaultStudyInterrupted,
    run_fault_study,
    study_rows,
)

T = TypeVar("T")


def _listing(kind: Callable[[str], T], what: str) -> Callable[[str], list[T]]:
    """An argparse type for a comma-separated list, naming the bad item in its error."""

    def parse(text: str) -> list[T]:
        items = [part.strip() for part in text.split(",") if part.strip()]
        if not items:
            raise argparse.ArgumentTypeError(f"give at least one {what}")
        parsed = []
        for item in items:
            try:
                parsed.append(kind(item))
            except ValueError:
                raise argparse.ArgumentTypeError(f"{item!r} is not a {what}") from None
        return parsed

    return parse


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument(
        "--rates", type=_listing(float, "fault rate"), default=[0.0, 0.1, 0.2, 0.3, 0.5]
    )
    parser.add_argument("--seeds", type=_listing(int, "whole-number seed"), default=[0, 1, 2])
    parser.add_argument("--methods", type=_listing(str, "method"), default=list(DEFAULT_METHODS))
    parser.add_argument("--out", type=Path, default=Path("runs/faults"))
    parser.add_argument("--workers", type=int, default=None, help="default: every core")
    parser.add_argument(
        "--sample", type=int, default=None, help="only the first N tasks of each appliance"
    )
    parser.add_argument("--appliances", type=_listing(str, "appliance id"), default=None)
    args = parser.parse_args()
    console = Console()
    try:
        study = run_fault_study(
            args.rates,
            args.methods,
            args.seeds,
            out=args.out,
            workers=args.workers,
            sample=args.sample,
            appliances=args.appliances,
        )
    except FaultStudyInterrupted as exc:
        console.print(
            f"[yellow]{exc}[/yellow]; finished tasks are kept: run the same command again to resume"
        )
        sys.exit(130)
    except ValueError as exc:  # bad rates, unknown methods or appliances (BenchError)
        console.print(f"[red]error[/red]: {exc}")
        sys.exit(2)
    table = Table(title=f"Fault study (mean over seeds {', '.join(map(str, study['seeds']))})")
    for column in ("method", "fault rate", "SR", "SPL", "reasoning", "execution", "n"):
        table.add_column(column, justify="left" if column == "method" else "right")
    for row in study_rows(study):
        table.add_row(*row)
    console.print(table)
    console.print(f"wrote {args.out / STUDY_FILE} and {args.out / PLOT_FILE}")


if __name__ == "__main__":
    main()
