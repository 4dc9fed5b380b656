"""``apbot bench`` and ``report``: run methods over the suite (resumable) and write the
run's report."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich import box
from rich.table import Table

from apbot.cli_common import console, errors, fail, feedback_mode, print_problems, split_names
from apbot.cli_llm import CacheOption, LLMOption
from apbot.cli_llm import setup as llm_setup
from apbot.model.problems import ModelError

if TYPE_CHECKING:
    pass


def bench(
    suite: Annotated[str, typer.Option(help="'bundled' or a suite directory.")] = "bundled",
    methods: Annotated[
        str | None, typer.Option(help="Comma-separated methods (default: all that need no LLM).")
    ] = None,
    categories: Annotated[
        str | None, typer.Option(help="Comma-separated appliance categories.")
    ] = None,
    appliances: Annotated[str | None, typer.Option(help="Comma-separated appliance ids.")] = None,
    sample: Annotated[
        int | None, typer.Option(help="Only the first N tasks of each appliance.")
    ] = None,
    workers: Annotated[
        int | None,
        typer.Option(help="Worker processes (default: one per core; 1 runs in this process)."),
    ] = None,
    out: Annotated[
        str, typer.Option(help="Run directory (results, summary, report).")
    ] = "runs/latest",
    belief: Annotated[
        str,
        typer.Option(
            help="The model methods work from: read (from the manual, offline), true, "
            "faulty:RATE or faulty:RATE:KIND,..."
        ),
    ] = "read",
    goal: Annotated[
        str,
        typer.Option(
            help="The goal methods get: read (parsed from the instruction against the belief) "
            "or given (the task's stored goal). Success is judged on the stored goal either way."
        ),
    ] = "read",
    learn: Annotated[
        bool,
        typer.Option(
            "--learn",
            help="Run each appliance's tasks in order, each from the belief the last one left.",
        ),
    ] = False,
    seed: Annotated[int, typer.Option(help="Seed for fault injection.")] = 0,
    feedback: Annotated[
        str,
        typer.Option(
            help="What the methods perceive: display (the panel's text, refusals only where "
            "the appliance signals them) or values (the paper's simulator: shown values by name)."
        ),
    ] = "display",
    rerun: Annotated[
        bool,
        typer.Option(help="Discard the directory's finished results and run everything again."),
    ] = False,
    no_report: Annotated[
        bool, typer.Option("--no-report", help="Do not write the report.")
    ] = False,
    llm: LLMOption = None,
    cache: CacheOption = None,
    llm_requests: Annotated[
        int | None, typer.Option(help="Stop cleanly after this many LLM requests.", min=0)
    ] = None,
    llm_tokens: Annotated[
        int | None, typer.Option(help="Stop cleanly after this many LLM tokens.", min=0)
    ] = None,
) -> None:
    """Run methods over the benchmark suite; resumable (finished tasks are skipped)."""
    import os

    from apbot.agent.registry import default_methods
    from apbot.cli_llm import describe, set_budget

    config = llm_setup(llm, cache)
    from apbot.bench.beliefs import BeliefError
    from apbot.bench.goals import GoalModeError
    from apbot.bench.results import ResultsError
    from apbot.bench.runner import BenchError, BenchOptions, run_benchmark

    _validated_suite(suite)
    chosen = split_names(methods)
    options = BenchOptions(
        suite=suite,
        methods=chosen if chosen is not None else default_methods(),
        categories=split_names(categories),
        appliances=split_names(appliances),
        sample=sample,
        workers=workers if workers is not None else os.cpu_count() or 1,
        out=out,
        belief=belief,
        seed=seed,
        rerun=rerun,
        feedback=feedback_mode(feedback),
        goal=goal,
        learn=learn,
    )
    set_budget(out, llm_requests, llm_tokens)
    try:
        outcome = run_benchmark(options)
    except (BenchError, BeliefError, GoalModeError) as exc:
        raise fail(str(exc), 2) from None
    except ResultsError as exc:
        raise fail(str(exc)) from None
    except OSError as exc:  # not foreseen by the runner: still one line, naming the file
        raise fail(f"{exc.filename or out}: {exc.strerror or exc}") from None
    except KeyboardInterrupt:  # before the run took over Ctrl-C: nothing was started
        raise fail("interrupted before any task ran", 130) from None
    _print_bench(outcome.summary)
    console.print(
        f"{outcome.ran} task(s) run, {outcome.skipped} already finished; results in {outcome.out}"
    )
    if belief.strip() == "read" or goal.strip() == "read":
        console.print(f"[dim]{describe(config)}[/dim]")
    if outcome.interrupted:
        errors.print(
            f"[yellow]stopped[/yellow] ({outcome.stopped_by}): {len(outcome.records)} finished "
            f"record(s) kept in {outcome.out}; run the same command again"
            f"{' without --rerun' if rerun else ''} to resume"
        )
        raise typer.Exit(outcome.exit_code)
    if not no_report:
        _bench_report(outcome.out)


def _validated_suite(name: str) -> None:
    """Load and validate the suite before any work starts (the runner reuses the loaded copy).

    Every problem is one line naming its file, line and task; exit 2 when there is one.
    """
    from apbot.bench.runner import cached_suite
    from apbot.bench.suite import validate_suite

    try:
        loaded = cached_suite(name)
    except FileNotFoundError as exc:
        raise fail(str(exc), 2) from None
    except ModelError as exc:
        print_problems(exc.problems, exc.source or name, stream=errors)
        raise fail(f"suite {name} cannot be loaded", 2) from None
    problems = [p for p in validate_suite(loaded) if p.severity == "error"]
    if problems:
        print_problems(problems, name, stream=errors)
        raise fail(f"suite {name} has {len(problems)} error(s); nothing was run", 2)


def _print_bench(summary: dict[str, Any]) -> None:
    """Overall figures per method, then SR / reasoning steps per category (the paper's table,
    transposed so it fits a terminal: one row per category)."""
    rows = summary["methods"]
    overall = Table(
        title=f"belief: {summary['belief']}",
        box=box.SIMPLE_HEAD,
        caption="steps: mean per task (reasoning = macro actions, execution = presses)",
    )
    overall.add_column("method", no_wrap=True)
    for column in ("SR", "SPL", "reasoning", "execution", "n"):
        overall.add_column(column, justify="right", no_wrap=True)
    for name, row in rows.items():
        o = row["overall"]
        overall.add_row(
            name,
            f"{o['sr']:.2f}",
            f"{o['spl']:.2f}",
            f"{o['reasoning_steps']:.2f}",
            f"{o['execution_steps']:.2f}",
            str(o["n"]),
        )
    console.print(overall)
    categories = sorted({c for row in rows.values() for c in row["categories"]})
    if not categories:
        return
    table = Table(title="SR / reasoning steps by category", box=box.SIMPLE_HEAD)
    table.add_column("category", no_wrap=True)
    for name in rows:  # long method names fold in the header; the cells never wrap
        table.add_column(name, justify="right", min_width=9, overflow="fold")
    for category in categories:
        cells = [row["categories"].get(category) for row in rows.values()]
        table.add_row(
            category, *(f"{c['sr']:.2f}/{c['reasoning_steps']:.1f}" if c else "–" for c in cells)
        )
    console.print(table)


def _bench_report(out: Path) -> None:
    try:
        from apbot.bench.report import write_report
    except ImportError:
        console.print("[dim]report skipped: apbot.bench.report is not available[/dim]")
        return
    for path in write_report(out):
        console.print(f"report: {path}")


def report_command(
    directory: Annotated[Path, typer.Argument(help="A run directory written by `apbot bench`.")],
) -> None:
    """Write report.md and a self-contained report.html for a benchmark run (one read of its
    results, so it may run while the bench still writes; a partial run says how far it got)."""
    from apbot.bench.report import ReportError, load_run, progress, write_files

    try:
        data = load_run(directory)
        paths = write_files(data)
    except ReportError as exc:
        raise fail(str(exc)) from None
    for path in paths[:2]:
        console.print(f"report: {path}")
    state = progress(data)
    if state.state == "partial":
        errors.print(f"[yellow]partial run[/yellow]: {state.text}")
    else:
        console.print(state.text)
