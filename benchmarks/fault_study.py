"""Fault study: SR and SPL of the closed loop and the open loop as the belief gets more wrong,
overall and per fault kind.

    python benchmarks/fault_study.py --rates 0,0.1,0.2,0.3,0.5 --seeds 0,1,2 --out runs/faults
        [--methods apbot,apbot-open-loop] [--feedback display|values] [--workers N]
        [--sample N] [--appliances a,b] [--kinds guard,display] [--single-kind]
    python benchmarks/fault_study.py --table runs/faults     # the per-kind table of a study
                                                             # or run directory, run nothing

One benchmark per (rate, seed) in OUT/rate-R-seed-S/ (each resumable: run the same command
again after an interruption); with --single-kind one per kind, rate and seed in
OUT/kind-K/rate-R-seed-S/, each kind injected on its own into the appliances it can hit.
OUT/fault_study.json holds the figures (averaged over the seeds, and per fault kind pooled
over the seeds); OUT/fault_study.png plots SR and SPL against the fault rate. Prints both
tables, with the false success claims, and the time the study took.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from rich.console import Console
from rich.table import Table

from apbot.bench.fault_study import (
    DEFAULT_METHODS,
    FEEDBACK_MODES,
    PLOT_FILE,
    STUDY_FILE,
    FaultStudyInterrupted,
    directory_table,
    kind_rows,
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


def _kind_table(title: str, rows: list[list[str]]) -> Table:
    table = Table(title=title)
    for column in ("fault kind", "method", "rate", "n", "SR", "SPL", "false claims"):
        table.add_column(column, justify="left" if column in ("fault kind", "method") else "right")
    for row in rows:
        table.add_row(*row)
    return table


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
    parser.add_argument(
        "--feedback",
        choices=FEEDBACK_MODES,
        default="display",
        help="what the methods perceive: the display text, or the adjusted values by name",
    )
    parser.add_argument(
        "--kinds",
        type=_listing(str, "fault kind"),
        default=None,
        help="inject only these kinds (with --single-kind: measure only these); default all",
    )
    parser.add_argument(
        "--single-kind",
        action="store_true",
        help="for each kind, faults from that kind only (OUT/kind-K/rate-R-seed-S)",
    )
    parser.add_argument(
        "--table",
        type=Path,
        default=None,
        metavar="DIR",
        help="print the per-kind table of a run or study directory and exit",
    )
    args = parser.parse_args()
    console = Console() if sys.stdout.isatty() else Console(width=120)  # whole names in a log
    if args.table is not None:
        try:
            rates, table = directory_table(args.table)
        except ValueError as exc:
            console.print(f"[red]error[/red]: {exc}")
            sys.exit(2)
        console.print(_kind_table(f"Per fault kind: {args.table}", kind_rows(table, rates)))
        return
    started = time.perf_counter()
    try:
        study = run_fault_study(
            args.rates,
            args.methods,
            args.seeds,
            out=args.out,
            workers=args.workers,
            sample=args.sample,
            appliances=args.appliances,
            feedback=args.feedback,
            single_kind=args.single_kind,
            kinds=args.kinds,
        )
    except FaultStudyInterrupted as exc:
        console.print(
            f"[yellow]{exc}[/yellow]; finished tasks are kept: run the same command again to resume"
        )
        sys.exit(130)
    except ValueError as exc:  # bad rates, methods, kinds or appliances (BenchError)
        console.print(f"[red]error[/red]: {exc}")
        sys.exit(2)
    seeds = ", ".join(map(str, study["seeds"]))
    mode = f"{study['mode']}, {study['feedback']} feedback"
    table = Table(title=f"Fault study ({mode}; mean over seeds {seeds})")
    for column in ("method", "fault rate", "SR", "SPL", "reasoning", "execution", "n"):
        table.add_column(column, justify="left" if column == "method" else "right")
    for row in study_rows(study):
        table.add_row(*row)
    console.print(table)
    title = f"Per fault kind ({mode}; runs pooled over seeds {seeds})"
    console.print(_kind_table(title, kind_rows(study["per_kind"], study["rates"])))
    claims = {m: sum(c.get("false_claims", [])) for m, c in study["methods"].items()}
    console.print(f"false success claims: {claims}")
    console.print(
        f"wrote {args.out / STUDY_FILE} and {args.out / PLOT_FILE} "
        f"in {time.perf_counter() - started:.0f} s"
    )


if __name__ == "__main__":
    main()
