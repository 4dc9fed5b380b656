"""``apbot suite …``: list, show, count, check and oracle-run the bundled benchmark suite."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich import box
from rich.console import Console
from rich.table import Table

from apbot.cli_common import checked_suite, chosen_appliances, console, errors, fail, print_problems

if TYPE_CHECKING:
    pass

suite_app = typer.Typer(no_args_is_help=True, help="The bundled benchmark suite.")


@suite_app.command("list")
def suite_list() -> None:
    """Every bundled appliance: category, controls, variables, tasks, manual words."""
    suite = checked_suite()
    rows = [
        (
            a.id,
            a.category,
            a.model.appliance.name,
            str(len(a.model.controls)),
            str(len(a.model.variables)),
            str(len(a.tasks)),
            str(a.manual_words),
        )
        for a in suite.appliances
    ]
    headers = ("id", "category", "name", "ctrl", "vars", "tasks", "words")
    table = Table(
        title=f"{len(suite.appliances)} appliances, {len(suite.tasks)} tasks",
        box=box.SIMPLE_HEAD,
        caption="ctrl, vars: controls and variables of the model; words: of the manual",
        padding=(0, 1, 0, 0),
        show_edge=False,
    )
    # ids and categories are what one copies: never cut or folded; the name wraps instead
    for i, header in enumerate(headers):
        if header == "name":
            table.add_column(header, min_width=12, overflow="fold")
        else:
            table.add_column(header, no_wrap=True, justify="right" if i > 2 else "left")
    for row in rows:
        table.add_row(*row)
    # rich squeezes no_wrap columns too when the console is too narrow for them; render at
    # the width they need then (a terminal wraps the line; the id stays whole)
    from rich.measure import Measurement

    natural = Measurement.get(console, console.options.update(width=10_000), table).maximum
    needed = natural - max(len(r[2]) for r in rows) + 12  # the name may wrap down to 12
    out = console
    if console.width < needed:
        out = Console(highlight=False, width=needed, file=console.file, color_system=None)
    out.print(table)


@suite_app.command("show")
def suite_show(
    appliance: str,
    lines: Annotated[int, typer.Option(help="Manual lines to show.", min=0)] = 25,
) -> None:
    """One appliance: the start of its manual, a model summary, and its tasks."""
    [item] = chosen_appliances([appliance])
    console.rule(f"{item.id} — {item.model.appliance.name} ({item.category})")
    manual = item.manual.splitlines()
    console.print(
        "\n".join(manual[:lines])
        + (
            f"\n[dim]… {len(manual) - lines} more lines, {item.manual_words} words[/dim]"
            if len(manual) > lines
            else ""
        )
    )
    console.rule("model")
    from apbot.bench.stats import appliance_features

    model = item.model
    console.print(
        f"controls: {len(model.controls)}, actions: {len(model.actions)}, "
        f"features: {', '.join(model.features)}"
    )
    console.print(
        "uses: " + ", ".join(sorted(k for k, v in appliance_features(model).items() if v))
    )
    table = Table()
    for column in ("variable", "type", "values"):
        table.add_column(column)
    from apbot.model.domain import all_values

    for name, var in model.variables.items():
        values = all_values(var)
        shown = ", ".join(str(v) for v in values[:6]) + (
            f", … ({len(values)})" if len(values) > 6 else ""
        )
        kind = var.type + (f" (by {var.depends_on})" if var.depends_on else "")
        table.add_row(name, kind, shown)
    console.print(table)
    console.rule("tasks")
    tasks = Table()
    for column in ("id", "instruction", "goal", "optimal"):
        tasks.add_column(column)
    for task in item.tasks:
        tasks.add_row(
            task.id,
            task.instruction,
            ", ".join(f"{k}={v}" for k, v in task.goal.items()),
            str(task.optimal_steps),
        )
    console.print(tasks)


@suite_app.command("stats")
def suite_stats(
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Per category: appliances, tasks, goal variables per task, and model features used."""
    from apbot.bench.stats import FEATURES, suite_statistics

    stats = suite_statistics(checked_suite())
    if as_json:
        print(json.dumps(stats, indent=2))
        return
    table = Table(
        title=f"{stats['appliances']} appliances, {stats['tasks']} tasks",
        caption="appliances using each model feature (2-key: two-control hold; "
        "dep.: programme-dependent settings; guard: child lock or running)",
        box=box.SIMPLE_HEAD,
        padding=(0, 1, 0, 0),
    )
    table.add_column("category", no_wrap=True, min_width=16)
    short = {
        "two_control_hold": "2-key",
        "dependent_settings": "dep.",
        "time_variables": "time",
        "piecewise": "piecew.",
        "guards": "guard",
    }
    for column in ("appl.", "tasks", "vars", *(short.get(f, f) for f in FEATURES)):
        table.add_column(column, justify="right", no_wrap=True, min_width=len(column))
    for name, row in stats["categories"].items():
        table.add_row(
            name,
            str(row["appliances"]),
            str(row["tasks"]),
            f"{row['goal_vars_per_task']:g}",
            *(str(row["features"][f]) for f in FEATURES),
        )
    table.add_row(
        "[bold]all[/bold]",
        str(stats["appliances"]),
        str(stats["tasks"]),
        "",
        *(f"[bold]{stats['features'][f]}[/bold]" for f in FEATURES),
    )
    console.print(table)
    constructs = Table(
        title="format constructs (docs/model-format.md)",
        box=box.SIMPLE_HEAD,
        padding=(0, 1, 0, 0),
    )
    constructs.add_column("construct", no_wrap=True)
    constructs.add_column("appliances", justify="right")
    for name, count in stats["constructs"].items():
        constructs.add_row(name, str(count))
    console.print(constructs)


@suite_app.command("check")
def suite_check(
    appliances: Annotated[
        list[str] | None, typer.Argument(help="Appliance ids (default: all).")
    ] = None,
) -> None:
    """Check appliances: model, panel, manual, tasks, oracle plans. Exit 1 on any error."""
    from apbot.bench.suite_check import check_appliance

    chosen = chosen_appliances(appliances)
    failed = 0
    for item in chosen:
        problems = check_appliance(item)
        bad = [p for p in problems if p.severity == "error"]
        failed += bool(bad)
        print_problems(problems, item.id)
        mark = "[red]✗[/red]" if bad else "[green]✓[/green]"
        console.print(f"{mark} {item.id}: {len(item.tasks)} tasks, {len(bad)} error(s)")
    if failed:
        raise fail(f"{failed} appliance(s) with errors")


@suite_app.command("oracle")
def suite_oracle(
    appliances: Annotated[
        list[str] | None, typer.Argument(help="Appliance ids (default: all).")
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Run the oracle (planner on the ground truth, executed on the simulator) on every task."""
    from apbot.bench.oracle import run_task, summarise
    from apbot.bench.suite import Suite

    chosen = chosen_appliances(appliances)
    suite = Suite("bundled", Path("."), chosen)
    results = []
    with console.status("planning and simulating…"):
        for appliance, task in suite.tasks:
            results.append(run_task(appliance, task))
    summary = summarise(results)
    failures = [r for r in results if not r.success]
    if as_json:
        print(
            json.dumps({"summary": summary, "failures": [r.__dict__ for r in failures]}, indent=2)
        )
    else:
        table = Table(title=f"Oracle on {len(results)} tasks of {len(chosen)} appliances")
        for column in (
            "category",
            "tasks",
            "success",
            "actions",
            "macro actions",
            "median plan ms",
            "worst plan ms",
        ):
            table.add_column(column, justify="right" if column != "category" else "left")
        for name, row in summary.items():
            style = "bold" if name == "all" else ""
            table.add_row(
                name,
                str(row["tasks"]),
                f"{row['success_rate']:.2f}",
                f"{row['mean_actions']:.1f}",
                f"{row['mean_macro_actions']:.1f}",
                f"{row['median_planning_ms']:.1f}",
                f"{row['worst_planning_ms']:.0f}",
                style=style,
            )
        console.print(table)
        for failure in failures:
            console.print(f"[red]✗[/red] {failure.appliance} {failure.task}: {failure.error}")
    if failures:
        raise typer.Exit(1)


@suite_app.command("fill-optimal")
def suite_fill_optimal(
    appliances: Annotated[
        list[str] | None, typer.Argument(help="Appliance ids (default: all).")
    ] = None,
) -> None:
    """Store the planner's optimal action count in every task (rewrites tasks.yaml)."""
    from apbot.bench.suite_check import FillError, fill_optimal

    chosen = chosen_appliances(appliances)
    for item in chosen:
        try:
            changed = fill_optimal(item)
        except FillError as exc:
            errors.print(f"[red]error:[/red] {exc} (nothing written for {item.id})")
            raise typer.Exit(1) from exc
        console.print(f"{item.id}: {changed} task(s) updated")
