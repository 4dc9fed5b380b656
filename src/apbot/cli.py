"""``apbot`` on the command line: check models, plan, drive a simulator, inspect the suite.

The commands are thin: each calls library functions that the tests use too.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich import box
from rich.console import Console
from rich.table import Table

from apbot.cli_llm import CacheOption, LLMOption, llm_app
from apbot.cli_llm import setup as llm_setup
from apbot.model.goal import GoalError
from apbot.model.problems import ModelError, Problem
from apbot.model.schema import ApplianceModel

if TYPE_CHECKING:
    from apbot.agent.environment import FeedbackMode
    from apbot.agent.episode import TraceEvent
    from apbot.bench.suite import Suite, SuiteAppliance, Task

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Operate home appliances by reading their manuals.",
)
suite_app = typer.Typer(no_args_is_help=True, help="The bundled benchmark suite.")
app.add_typer(suite_app, name="suite")
app.add_typer(llm_app, name="llm")
console = Console(highlight=False, soft_wrap=True)
errors = Console(stderr=True, highlight=False, soft_wrap=True)

ModelArg = Annotated[
    str,
    typer.Argument(
        help="A model file, an appliance directory, an example name or a bundled appliance id."
    ),
]


def _fail(message: str, code: int = 1) -> typer.Exit:
    errors.print(f"[red]error:[/red] {message}")
    return typer.Exit(code)


def resolve_model(spec: str) -> tuple[ApplianceModel, str]:
    """Load a model from a path, an example name or a bundled suite id."""
    from apbot.examples import example_dir, example_names
    from apbot.model.load import load_model

    path = Path(spec)
    if path.is_dir() and (path / "model.yaml").exists():
        path = path / "model.yaml"
    if path.exists():
        return load_model(path), str(path)
    if spec in example_names():
        source = example_dir() / f"{spec}.yaml"
        return load_model(source), str(source)
    from apbot.bench.suite import bundled_suite_dir

    bundled = bundled_suite_dir() / spec / "model.yaml"
    if bundled.exists():
        return load_model(bundled), str(bundled)
    examples = ", ".join(example_names())
    raise FileNotFoundError(
        f"{spec!r} is not a model file, an example ({examples}) or a bundled appliance id"
    )


def _print_problems(problems: list[Problem], source: str, stream: Console | None = None) -> None:
    """One line per problem: severity, file:line, path, message and the check's name (at
    most a hundred, then a line counting the rest)."""
    from apbot.model.load import capped

    for problem in capped(problems):
        colour = "red" if problem.severity == "error" else "yellow"
        where = problem.source or source
        location = f"{where}:{problem.line}" if problem.line else where
        (stream or console).print(
            f"[{colour}]{problem.severity}[/{colour}] {location}: "
            + (f"[bold]{problem.where}[/bold]: " if problem.path else "")
            + f"{problem.message} [dim]\\[{problem.check}][/dim]"
        )


@app.command()
def check(
    model: ModelArg,
    goal: Annotated[
        list[str] | None, typer.Option("--goal", "-g", help="Also check a goal NAME=VALUE.")
    ] = None,
) -> None:
    """Validate a model (or a suite appliance directory); exit 1 if it has errors."""
    from apbot.model.load import line_of, load_model
    from apbot.model.validate import check_goal
    from apbot.sim.checks import check_model

    path = Path(model)
    try:
        if path.is_dir() and (path / "model.yaml").exists() and (path / "tasks.yaml").exists():
            problems, source = _check_appliance_dir(path), str(path)
        else:
            if path.is_dir() and (path / "model.yaml").exists():
                path = path / "model.yaml"  # a directory with a model but no tasks
            loaded, source = (
                resolve_model(model)
                if not path.exists()
                else (load_model(path, check=False), str(path))
            )
            text = Path(source).read_text(encoding="utf-8") if Path(source).exists() else None
            problems = [
                Problem(p.path, p.message, p.check, p.severity, line_of(text, p.path))
                for p in check_model(loaded)
            ]
            if goal:
                from apbot.model.goal import split_assignments

                problems += check_goal(loaded, split_assignments(goal))
    except ModelError as exc:
        _print_problems(exc.problems, exc.source or model)
        raise _fail(f"{len([p for p in exc.problems if p.severity == 'error'])} error(s)") from None
    except (FileNotFoundError, GoalError) as exc:
        raise _fail(str(exc)) from None
    _print_problems(problems, source)
    count = len([p for p in problems if p.severity == "error"])
    if count:
        raise _fail(f"{count} error(s) in {source}")
    warnings = len(problems) - count
    console.print(f"[green]ok[/green] {source}" + (f" ({warnings} warning(s))" if warnings else ""))


def _chosen(appliances: list[str] | None) -> list[SuiteAppliance]:
    """The named bundled appliances (loading only those), or the whole suite.

    Exits with a clear message for an unknown id or a broken appliance directory.
    """
    if not appliances:
        return _suite().appliances
    return [_bundled(name) for name in appliances]


def _bundled(appliance_id: str, code: int = 1) -> SuiteAppliance:
    """One bundled appliance, loaded and checked alone (not the whole suite: ``apbot run``
    needs one of 45); an unknown id names the closest one."""
    from apbot.bench.suite import bundled_suite_dir, load_appliance
    from apbot.model.values import closest_matches

    ids = sorted(p.name for p in bundled_suite_dir().iterdir() if (p / "model.yaml").exists())
    if appliance_id not in ids:  # a name, never a path
        close = closest_matches(appliance_id, ids, limit=1)
        hint = f"; did you mean {close[0]!r}?" if close else " (see `apbot suite list`)"
        raise _fail(f"no appliance {appliance_id!r} in the bundled suite{hint}", code)
    directory = bundled_suite_dir() / appliance_id
    try:
        return load_appliance(directory, check=True)
    except ModelError as exc:
        _print_problems(exc.problems, exc.source or appliance_id)
        raise _fail(f"{appliance_id} cannot be loaded", code) from None


def _suite() -> Suite:
    """The bundled suite, or a clear error naming the broken appliance files."""
    from apbot.bench.suite import load_suite

    try:
        return load_suite(check=True)
    except ModelError as exc:
        _print_problems(exc.problems, exc.source or "suite")
        raise _fail("the bundled suite cannot be loaded") from None


def _check_appliance_dir(path: Path) -> list[Problem]:
    from apbot.bench.suite import load_appliance
    from apbot.bench.suite_check import check_appliance

    return check_appliance(load_appliance(path, check=False))


@app.command("plan")
def plan_command(
    model: ModelArg,
    goal: Annotated[list[str], typer.Option("--goal", "-g", help="NAME=VALUE, repeatable.")],
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Plan the shortest action sequence from the initial state to a goal."""
    from apbot.plan.plan import Unreachable, plan

    try:
        loaded, _ = resolve_model(model)
        found = plan(loaded, None, goal)
    except ModelError as exc:
        _print_problems(exc.problems, exc.source or model)
        raise _fail("the model has errors") from None
    except (FileNotFoundError, GoalError) as exc:
        raise _fail(str(exc)) from None
    except Unreachable as exc:
        raise _fail(f"unreachable: {exc.reason}") from None
    if as_json:
        console.print_json(
            json.dumps(
                {
                    "goal": found.goal,
                    "actions": len(found),
                    "macro_actions": [
                        {
                            "feature": m.feature,
                            "actions": [str(a) for a in m.actions],
                            "expect": m.expect,
                        }
                        for m in found.macro_actions
                    ],
                }
            )
        )
        return
    table = Table(
        title=f"{len(found.macro_actions)} macro actions, {len(found)} actions "
        f"({found.seconds * 1000:.1f} ms)"
    )
    table.add_column("#", justify="right")
    table.add_column("macro action")
    table.add_column("actions")
    table.add_column("expect")
    for i, macro in enumerate(found.macro_actions, 1):
        table.add_row(
            str(i),
            macro.feature,
            _compress([str(a) for a in macro.actions]),
            ", ".join(f"{k}={v}" for k, v in macro.expect.items()),
        )
    console.print(table)


def _compress(actions: list[str]) -> str:
    """``[a, a, a, b]`` -> ``a ×3, b``."""
    parts: list[str] = []
    for action in actions:
        if parts and parts[-1].split(" ×")[0] == action:
            count = int(parts[-1].split(" ×")[1]) + 1 if " ×" in parts[-1] else 2
            parts[-1] = f"{action} ×{count}"
        else:
            parts.append(action)
    return ", ".join(parts)


@app.command()
def sim(
    model: ModelArg,
    script: Annotated[
        Path | None, typer.Option(help="Read actions from a file, one per line.")
    ] = None,
) -> None:
    """Drive a simulator by hand: type an action, see the display. `help` lists actions."""
    from apbot.sim.simulator import Simulator, UnknownAction

    try:
        loaded, _ = resolve_model(model)
    except ModelError as exc:
        _print_problems(exc.problems, exc.source or model)
        raise _fail("the model has errors") from None
    except FileNotFoundError as exc:
        raise _fail(str(exc)) from None
    simulator = Simulator(loaded)
    console.print(
        f"[bold]{loaded.appliance.name or loaded.appliance.id}[/bold] — "
        "type an action (`help`, `state`, `reset`, `quit`)"
    )
    console.print(f"display: [cyan]{simulator.observe().display!r}[/cyan]")
    try:
        lines = script.read_text(encoding="utf-8").splitlines() if script else None
    except (OSError, UnicodeDecodeError) as exc:
        raise _fail(f"cannot read the script {script}: {exc}") from None
    while True:
        if lines is not None:
            if not lines:
                break
            line = lines.pop(0).strip()
            console.print(f"> {line}")
        else:
            try:
                line = console.input("> ").strip()
            except (EOFError, KeyboardInterrupt):
                break
        if not line or line.startswith("#"):
            continue
        if line in ("quit", "exit"):
            break
        if line == "help":
            console.print(", ".join(simulator.actions))
            continue
        if line == "state":
            console.print(simulator.assignment())
            continue
        if line == "reset":
            console.print(f"display: [cyan]{simulator.reset().display!r}[/cyan]")
            continue
        name, _, seconds = line.partition(" ")
        try:
            held = float(seconds) if seconds else None
            if held is not None and not (math.isfinite(held) and held > 0):
                raise ValueError(seconds)
            observation = simulator.step(name, held)
        except UnknownAction as exc:
            console.print(f"[red]{exc}[/red]")
            continue
        except ValueError:
            console.print(f"[red]{seconds!r} is not a positive number of seconds[/red]")
            continue
        status = "" if observation.accepted else f"  [yellow]refused: {observation.reason}[/yellow]"
        console.print(f"display: [cyan]{observation.display!r}[/cyan]{status}")


# --- suite ------------------------------------------------------------------------------------


@suite_app.command("list")
def suite_list() -> None:
    """Every bundled appliance: category, controls, variables, tasks, manual words."""
    suite = _suite()
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
    [item] = _chosen([appliance])
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

    stats = suite_statistics(_suite())
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

    chosen = _chosen(appliances)
    failed = 0
    for item in chosen:
        problems = check_appliance(item)
        bad = [p for p in problems if p.severity == "error"]
        failed += bool(bad)
        _print_problems(problems, item.id)
        mark = "[red]✗[/red]" if bad else "[green]✓[/green]"
        console.print(f"{mark} {item.id}: {len(item.tasks)} tasks, {len(bad)} error(s)")
    if failed:
        raise _fail(f"{failed} appliance(s) with errors")


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

    chosen = _chosen(appliances)
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

    chosen = _chosen(appliances)
    for item in chosen:
        try:
            changed = fill_optimal(item)
        except FillError as exc:
            errors.print(f"[red]error:[/red] {exc} (nothing written for {item.id})")
            raise typer.Exit(1) from exc
        console.print(f"{item.id}: {changed} task(s) updated")


# --- goals ------------------------------------------------------------------------------------


@app.command("goal")
def goal_command(
    model: ModelArg,
    instruction: Annotated[str, typer.Argument(help="What the user said, in quotes.")],
    as_json: Annotated[bool, typer.Option("--json", help="Print the goal as JSON.")] = False,
    manual: Annotated[
        Path | None,
        typer.Option(
            help="The manual, for values the panel shows only as codes (default: the "
            "manual.md beside the model, if there is one)."
        ),
    ] = None,
    llm: LLMOption = None,
    cache: CacheOption = None,
) -> None:
    """Parse an instruction into a goal over MODEL's variables (offline parser, or --llm)."""
    from apbot.read.goal import GoalParseError, parse_instruction

    config = llm_setup(llm, cache)

    try:
        belief, source = resolve_model(model)
    except (FileNotFoundError, ModelError) as exc:
        if isinstance(exc, ModelError):
            _print_problems(exc.problems, exc.source or model)
        message = str(exc) if isinstance(exc, FileNotFoundError) else "the model is invalid"
        raise _fail(message) from None
    beside = Path(source).parent / "manual.md"
    text = ""
    if manual is not None or beside.is_file():
        try:
            text = (manual or beside).read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise _fail(f"{manual or beside}: cannot read the manual ({exc})") from None
    try:
        if config is not None:
            from apbot.cli_llm import goal_parser

            goal = goal_parser(config)(belief, instruction, text)
        else:
            goal = parse_instruction(belief, instruction, text)
    except (GoalParseError, ValueError) as exc:
        raise _fail(f"cannot read the instruction: {exc}") from None
    if as_json:
        console.print_json(json.dumps(goal))
        return
    if not goal:
        console.print("[yellow]the instruction names no setting of this model[/yellow]")
    for name, value in goal.items():
        console.print(f"{name} = {value}")


@app.command("eval-goals")
def eval_goals(
    suite: Annotated[str, typer.Option(help="'bundled' or a suite directory.")] = "bundled",
    categories: Annotated[
        str | None, typer.Option(help="Comma-separated appliance categories.")
    ] = None,
    appliances: Annotated[
        str | None, typer.Option(help="Comma-separated appliance ids or patterns ('*_4,*_5').")
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print the scores as JSON.")] = False,
    sample: Annotated[
        int | None, typer.Option(help="Only the first N tasks of each appliance.", min=1)
    ] = None,
    llm: LLMOption = None,
    cache: CacheOption = None,
) -> None:
    """Exact accuracy of the goal parser (offline, or --llm) on a suite's instructions."""
    from apbot.bench.goal_eval import evaluate_goals
    from apbot.bench.suite import load_suite

    try:
        loaded = _suite() if suite == "bundled" else load_suite(suite)
    except (FileNotFoundError, ModelError) as exc:
        if isinstance(exc, ModelError):
            _print_problems(exc.problems, exc.source or suite)
        message = str(exc) if isinstance(exc, FileNotFoundError) else "the suite is invalid"
        raise _fail(message) from None
    config = llm_setup(llm, cache)
    parser = None
    if config is not None:
        from apbot.cli_llm import goal_parser

        parser = goal_parser(config)
    score = evaluate_goals(loaded, _names(categories), _names(appliances), parser, sample)
    if score.n == 0:
        raise _fail("no tasks match the chosen categories and appliances")
    if as_json:
        console.print_json(json.dumps(score.as_json()))
        return
    table = Table(box=box.SIMPLE)
    for column in ("category", "accuracy", "tasks"):
        table.add_column(column)
    for name, entry in score.as_json()["categories"].items():
        table.add_row(name, f"{entry['accuracy']:.3f}", str(entry["n"]))
    table.add_row("overall", f"{score.accuracy:.3f}", str(score.n))
    console.print(table)
    for miss in score.misses:
        console.print(f"[red]miss[/red] {miss.appliance} {miss.task}: {miss.instruction}")
        console.print(f"    expected {miss.expected}")
        console.print(f"    parsed   {miss.error or miss.parsed}")


# --- bench ------------------------------------------------------------------------------------


def _names(text: str | None) -> list[str] | None:
    """``"a, b,"`` -> ``["a", "b"]``; None when not given."""
    if text is None:
        return None
    return [part.strip() for part in text.split(",") if part.strip()]


@app.command()
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
    chosen = _names(methods)
    options = BenchOptions(
        suite=suite,
        methods=chosen if chosen is not None else default_methods(),
        categories=_names(categories),
        appliances=_names(appliances),
        sample=sample,
        workers=workers if workers is not None else os.cpu_count() or 1,
        out=out,
        belief=belief,
        seed=seed,
        rerun=rerun,
        feedback=_feedback_mode(feedback),
        goal=goal,
        learn=learn,
    )
    set_budget(out, llm_requests, llm_tokens)
    try:
        outcome = run_benchmark(options)
    except (BenchError, BeliefError, GoalModeError) as exc:
        raise _fail(str(exc), 2) from None
    except ResultsError as exc:
        raise _fail(str(exc)) from None
    except OSError as exc:  # not foreseen by the runner: still one line, naming the file
        raise _fail(f"{exc.filename or out}: {exc.strerror or exc}") from None
    except KeyboardInterrupt:  # before the run took over Ctrl-C: nothing was started
        raise _fail("interrupted before any task ran", 130) from None
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
        raise _fail(str(exc), 2) from None
    except ModelError as exc:
        _print_problems(exc.problems, exc.source or name, stream=errors)
        raise _fail(f"suite {name} cannot be loaded", 2) from None
    problems = [p for p in validate_suite(loaded) if p.severity == "error"]
    if problems:
        _print_problems(problems, name, stream=errors)
        raise _fail(f"suite {name} has {len(problems)} error(s); nothing was run", 2)


def _feedback_mode(text: str) -> FeedbackMode:
    """A ``--feedback`` value, checked (typer's Enum choices would print as classes)."""
    from apbot.agent.environment import FEEDBACK_MODES

    for mode in FEEDBACK_MODES:
        if text == mode:
            return mode
    raise _fail(f"--feedback must be one of {', '.join(FEEDBACK_MODES)} (got {text!r})", 2)


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


@app.command("report")
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
        raise _fail(str(exc)) from None
    for path in paths[:2]:
        console.print(f"report: {path}")
    state = progress(data)
    if state.state == "partial":
        errors.print(f"[yellow]partial run[/yellow]: {state.text}")
    else:
        console.print(state.text)


@app.command("run")
def run_command(
    appliance: Annotated[str, typer.Argument(help="A bundled appliance id.")],
    instruction: Annotated[
        str,
        typer.Argument(help="What to do, in any words — or a task id (t01…) of the appliance."),
    ],
    goal: Annotated[
        list[str] | None,
        typer.Option(
            "--goal",
            "-g",
            help="Give the goal as NAME=VALUE (repeatable) instead of reading it from the "
            "instruction; names and values are the true appliance's.",
        ),
    ] = None,
    method: Annotated[str, typer.Option(help="The method to run.")] = "apbot",
    belief: Annotated[
        str | None,
        typer.Option(
            help="The model the method works from: read (from the manual, by the LLM with "
            "--llm, else offline; the default), true (the default with -g, whose names are the "
            "truth's), faulty:RATE or faulty:RATE:KIND,..."
        ),
    ] = None,
    seed: Annotated[int, typer.Option(help="Seed for fault injection.")] = 0,
    feedback: Annotated[
        str, typer.Option(help="What the method perceives: display, values or image.")
    ] = "display",
    show_exploration: Annotated[
        bool, typer.Option(help="Print every exploring press, not only a count.")
    ] = False,
    parse_goal_text: Annotated[
        bool, typer.Option("--parse-goal", hidden=True, help="The default now; ignored.")
    ] = False,
    llm: LLMOption = None,
    cache: CacheOption = None,
) -> None:
    """Run one instruction live: every macro action, press, display, check and repair.

    The goal is read from the instruction against the method's belief (the offline goal
    parser) unless -g gives it. A task of the appliance (its id or its instruction) is judged
    on the true simulator against the task's stored goal; any other instruction has no stored
    goal, so the verdict is the agent's own.
    """
    from apbot.bench.beliefs import BeliefError
    from apbot.bench.runner import run_task
    from apbot.bench.suite import Task
    from apbot.cli_llm import describe
    from apbot.model.goal import parse_goal, split_assignments

    config = llm_setup(llm, cache)
    found = _bundled(appliance, 2)
    task = _task_for(found, instruction)
    mode = _feedback_mode(feedback)
    belief = belief if belief is not None else ("true" if goal else "read")
    if belief.strip() == "read" or not goal:
        console.print(f"[dim]{describe(config)}[/dim]")
    if goal:
        try:
            goal_values = split_assignments(goal)
            parse_goal(found.model, goal_values)
        except GoalError as exc:
            raise _fail(str(exc), 2) from None
        # a live task is not a line of tasks.yaml: the instruction is the user's own words
        # (any length), and the goal was just checked against the appliance
        task = Task.model_construct(
            id=task.id if task else "live",
            instruction=task.instruction if task else instruction,
            goal=goal_values,
            optimal_steps=None,
        )
    printer = _LivePrinter(show_exploration)
    if task is None:
        _run_free(found, instruction, method, belief, seed, mode, printer)
        return
    console.print(f"[bold]{found.id}[/bold] · {task.instruction}")
    console.print(f"stored goal: {', '.join(f'{k}={v}' for k, v in task.goal.items())}")
    try:
        record = run_task(
            found,
            task,
            method,
            belief,
            seed,
            observer=printer,
            feedback=mode,
            goal="given" if goal else "read",
        )
    except BeliefError as exc:
        raise _fail(str(exc), 2) from None
    except (KeyError, ValueError) as exc:
        raise _fail(str(exc.args[0] if isinstance(exc, KeyError) else exc), 2) from None
    printer.flush()
    if record.parsed_goal is not None:
        console.print(f"read goal: {', '.join(f'{k}={v}' for k, v in record.parsed_goal.items())}")
    verdict = "[green]success[/green]" if record.success else "[red]failure[/red]"
    console.print(
        f"{verdict}: {record.reasoning_steps} reasoning steps, "
        f"{record.execution_steps} actions (optimal {record.optimal_steps}), "
        f"SPL {record.spl:.2f}"
    )
    if record.failure:
        console.print(f"[red]{record.failure}[/red]")
    raise typer.Exit(0 if record.success else 1)


def _run_free(
    found: SuiteAppliance,
    instruction: str,
    method: str,
    belief: str,
    seed: int,
    mode: FeedbackMode,
    printer: _LivePrinter,
) -> None:
    """An instruction that is none of the tasks: read its goal against the belief and run it;
    there is no stored goal, so the agent's verdict is all there is (said so)."""
    from apbot.agent.environment import SimulatorEnvironment
    from apbot.bench.beliefs import BeliefError, belief_model
    from apbot.operate import operate

    try:
        model, _faults = belief_model(found, belief, seed)
    except (BeliefError, ValueError) as exc:
        raise _fail(str(exc), 2) from None
    if mode == "image":  # the rendered panel, grounded from its photo, as `bench` does
        from apbot.bench.runner import image_environment

        try:
            env: Any = image_environment(found, found.model.actions, seed)
        except ImportError as exc:
            raise _fail(f"--feedback image needs the vision extra ({exc})", 2) from None
    else:
        env = SimulatorEnvironment(found.model, mode)
    console.print(f"[bold]{found.id}[/bold] · {instruction}")
    done = operate(
        found.manual,
        list(env.actions),
        instruction,
        env,
        method=method,
        observer=printer,
        model=model,
    )
    printer.flush()
    if done.goal_error:
        raise _fail(f"cannot read the instruction: {done.goal_error}", 2)
    console.print(f"read goal: {', '.join(f'{k}={v}' for k, v in done.goal.items())}")
    verdict = "[green]done[/green]" if done.success else "[red]not done[/red]"
    console.print(
        f"{verdict} (the agent's verdict: a free instruction has no stored goal to judge by): "
        f"{done.episode.reasoning_steps} reasoning steps, {env.steps} actions"
    )
    if done.episode.failure:
        console.print(f"[red]{done.episode.failure}[/red]")
    raise typer.Exit(0 if done.success else 1)


def _task_for(appliance: SuiteAppliance, text: str) -> Task | None:
    """The appliance's task with this id or instruction (or one very close to it)."""
    import difflib

    wanted = text.strip().casefold()
    for task in appliance.tasks:
        if wanted in (task.id, task.instruction.strip().casefold()):
            return task
    scores = [
        (difflib.SequenceMatcher(None, wanted, t.instruction.casefold()).ratio(), t)
        for t in appliance.tasks
    ]
    best = max(scores, key=lambda pair: pair[0], default=None)
    return best[1] if best is not None and best[0] >= 0.85 else None


class _LivePrinter:
    """Prints trace events as the agent produces them; runs of exploration are summarised."""

    def __init__(self, show_exploration: bool) -> None:
        self.show_exploration = show_exploration
        self.exploring = 0

    def flush(self) -> None:
        if self.exploring:
            console.print(f"    [dim]… explored with {self.exploring} presses[/dim]")
            self.exploring = 0

    def __call__(self, event: TraceEvent) -> None:
        if event.kind == "action" and event.exploring and not self.show_exploration:
            self.exploring += 1
            return
        self.flush()
        if event.kind == "macro":
            target = ", ".join(f"{k}={v}" for k, v in event.expected.items())
            console.print(f"[bold]{event.step:>2}. {event.text}[/bold] [dim]→ {target}[/dim]")
        elif event.kind == "action":
            mark = "[yellow]explore[/yellow] " if event.exploring else ""
            refused = " [red](refused)[/red]" if not event.accepted else ""
            console.print(
                f"    {mark}{event.action}: [cyan]{event.display or '(dark)'}[/cyan]{refused}"
            )
        elif event.kind == "check":
            if event.text == "ok":
                console.print("    [green]✓ as expected[/green]")
            else:
                seen = ", ".join(f"{k}={v}" for k, v in event.values.items())
                console.print(f"    [red]✗ mismatch[/red] {seen}")
        elif event.kind in ("explore", "repair"):
            colour = "magenta" if event.kind == "repair" else "yellow"
            console.print(f"    [{colour}]{event.kind}: {event.text}[/{colour}]")
        elif event.kind == "stop":
            console.print(f"[dim]stop: {event.text}[/dim]")


@app.command("read")
def read_command(
    manual: Annotated[Path, typer.Argument(help="The manual: Markdown or plain text.")],
    actions: Annotated[
        Path | None,
        typer.Option(help="A file of action names (one a line, or a YAML/JSON list)."),
    ] = None,
    appliance: Annotated[
        str | None, typer.Option(help="Take the action names of this bundled appliance.")
    ] = None,
    out: Annotated[Path | None, typer.Option("-o", "--out", help="Write the model here.")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print the report as JSON.")] = False,
    llm: LLMOption = None,
    cache: CacheOption = None,
    from_scratch: Annotated[
        bool,
        typer.Option(
            help="With --llm: no draft from the offline reader (it still gives the "
            "action specs and guards)."
        ),
    ] = False,
) -> None:
    """Read a manual into a model (offline, or --llm); print where each part came from."""
    from apbot.model.load import model_to_yaml, read_text
    from apbot.read import ReaderError, read_manual
    from apbot.read.commands import action_names

    if (actions is None) == (appliance is None):
        raise _fail("give exactly one of --actions FILE or --appliance ID")
    try:
        names = action_names(actions) if actions else list(_bundled(str(appliance)).model.actions)
        config = llm_setup(llm, cache)
        if config is None:
            reading = read_manual(read_text(manual), names, category=manual.stem)
        else:
            from apbot.cli_llm import read_with_llm

            reading = read_with_llm(config, read_text(manual), names, manual.stem, from_scratch)
    except (ReaderError, OSError, ModelError) as exc:
        raise _fail(str(exc)) from None
    text = model_to_yaml(reading.model)
    if out:
        out.write_text(text, encoding="utf-8")
    if as_json:
        console.print_json(json.dumps({"notes": reading.report.to_json()}))
    else:
        console.print(reading.report.render(), markup=False)
        if not out:
            console.print(text, markup=False)


@app.command("eval-reader")
def eval_reader(
    suite: Annotated[str, typer.Option(help="'bundled' or a suite directory.")] = "bundled",
    categories: Annotated[
        str | None, typer.Option(help="Comma-separated categories (default: all).")
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
    appliances: Annotated[
        str | None, typer.Option(help="Comma-separated appliance ids or patterns ('*_1').")
    ] = None,
    llm: LLMOption = None,
    cache: CacheOption = None,
    from_scratch: Annotated[
        bool, typer.Option(help="With --llm: no draft from the offline reader.")
    ] = False,
) -> None:
    """Precision and recall of the reader (offline, or --llm) against the ground truth."""
    from apbot.bench.suite import load_suite
    from apbot.read.commands import score_table
    from apbot.read.evaluate import evaluate

    try:
        loaded = load_suite(suite)
    except (FileNotFoundError, ModelError) as exc:
        raise _fail(str(exc)) from None
    wanted = set(_names(categories) or [])
    chosen = [a for a in loaded.appliances if not wanted or a.category in wanted]
    if appliances:
        from fnmatch import fnmatchcase

        patterns = _names(appliances) or []
        chosen = [a for a in chosen if any(fnmatchcase(a.id, p) for p in patterns)]
    if not chosen:
        raise _fail(f"no appliances in categories {sorted(wanted)}")
    config = llm_setup(llm, cache)
    extra: dict[str, Any] = {}
    if config is None:
        result = evaluate((a.category, a.manual, list(a.model.actions), a.model) for a in chosen)
    else:
        from apbot.cli_llm import evaluate_reader

        result, extra = evaluate_reader(config, chosen, from_scratch)
    if as_json:
        console.print_json(json.dumps({**result.to_json(), **extra}))
    else:
        console.print(score_table(result), markup=False)


@app.command("render")
def render_command(
    appliance: Annotated[str, typer.Argument(help="A bundled appliance id.")],
    out: Annotated[Path, typer.Option("-o", "--out", help="Where to write the PNG.")] = Path(
        "panel.png"
    ),
    state: Annotated[
        list[str] | None,
        typer.Option("--state", "-s", help="VAR=VALUE to show (reached by planned presses)."),
    ] = None,
    level: Annotated[str, typer.Option(help="Camera: clean, mild or strong.")] = "clean",
    seed: Annotated[int, typer.Option(help="Camera seed.")] = 0,
    style: Annotated[str | None, typer.Option(help="Display style: dot or seg.")] = None,
) -> None:
    """Draw an appliance's panel, its display showing the state (seeded camera variations)."""
    from apbot.vision.render import render_state

    found = _bundled(appliance)
    if style not in (None, "dot", "seg"):
        raise _fail(f"--style must be dot or seg (got {style!r})", 2)
    try:
        chosen_style: Any = style
        text = render_state(found, dict(_pairs(state or [])), out, level, seed, chosen_style)
    except (ValueError, KeyError) as exc:
        raise _fail(str(exc), 2) from None
    console.print(f"{out}: {found.id}, display {text!r}", markup=False)


def _pairs(items: list[str]) -> list[tuple[str, str]]:
    pairs = []
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise _fail(f"--state wants VAR=VALUE (got {item!r})", 2)
        pairs.append((name.strip(), value.strip()))
    return pairs


@app.command("ground")
def ground_command(
    suite: Annotated[str, typer.Option(help="'bundled' or a suite directory.")] = "bundled",
    appliances: Annotated[
        str | None, typer.Option(help="Comma-separated appliance ids (default: all).")
    ] = None,
    variations: Annotated[int, typer.Option(help="Camera variations per panel.")] = 2,
    displays: Annotated[int, typer.Option(help="Displays read per appliance (0: none).")] = 14,
    level: Annotated[str, typer.Option(help="Camera: clean, mild or strong.")] = "mild",
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
    mistakes: Annotated[bool, typer.Option(help="List every wrong grounding/reading.")] = False,
) -> None:
    """Grounding precision/recall/F1 per category and display-reading accuracy from photos."""
    from apbot.bench.suite import load_suite
    from apbot.vision.evaluate import evaluate_display, evaluate_grounding

    try:
        loaded = load_suite(suite)
    except (FileNotFoundError, ModelError) as exc:
        raise _fail(str(exc)) from None
    wanted = set(_names(appliances) or [])
    chosen = [a for a in loaded.appliances if not wanted or a.id in wanted]
    if not chosen:
        raise _fail(f"no appliances match {sorted(wanted)}")
    report = evaluate_grounding(chosen, variations, level)
    if displays > 0:
        evaluate_display(chosen, displays, level, report)
    result = report.as_dict()
    if as_json:
        console.print_json(json.dumps(result))
    else:
        overall = result["grounding"]["overall"]
        console.print(
            f"grounding: P {overall['precision']:.3f}  R {overall['recall']:.3f}  "
            f"F1 {overall['f1']:.3f}  ({overall['total']} actions)"
        )
        for category, row in result["grounding"]["categories"].items():
            console.print(f"  {category:18s} P {row['precision']:.3f}  R {row['recall']:.3f}  "
                          f"F1 {row['f1']:.3f}")  # fmt: skip
        display = result["display"]
        console.print(f"display: accuracy {display['accuracy']:.3f} over {display['n']} photos "
                      f"{display['styles']}")  # fmt: skip
        console.print(f"timing: {result['timing']}")
    if mistakes:
        for line in report.mistakes:
            console.print(line, markup=False)


def main() -> None:
    """Console entry point."""
    app()


if __name__ == "__main__":
    main()
