"""``apbot check``, ``plan`` and ``sim``: one model at a time — validate it, plan over it,
drive its simulator by hand."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.table import Table

from apbot.cli_common import ModelArg, console, fail, print_problems, resolve_model
from apbot.model.goal import GoalError
from apbot.model.problems import ModelError, Problem

if TYPE_CHECKING:
    pass


def check(
    model: ModelArg,
    goal: Annotated[
        list[str] | None, typer.Option("--goal", "-g", help="Also check a goal NAME=VALUE.")
    ] = None,
) -> None:
    """Validate a model (or a suite appliance directory); exit 1 if it has errors."""
    from apbot.model.load import load_model
    from apbot.model.validate import check_goal
    from apbot.model.yaml_text import line_of
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
        print_problems(exc.problems, exc.source or model)
        raise fail(f"{len([p for p in exc.problems if p.severity == 'error'])} error(s)") from None
    except (FileNotFoundError, GoalError) as exc:
        raise fail(str(exc)) from None
    print_problems(problems, source)
    count = len([p for p in problems if p.severity == "error"])
    if count:
        raise fail(f"{count} error(s) in {source}")
    warnings = len(problems) - count
    console.print(f"[green]ok[/green] {source}" + (f" ({warnings} warning(s))" if warnings else ""))


def _check_appliance_dir(path: Path) -> list[Problem]:
    from apbot.bench.suite import load_appliance
    from apbot.bench.suite_check import check_appliance

    return check_appliance(load_appliance(path, check=False))


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
        print_problems(exc.problems, exc.source or model)
        raise fail("the model has errors") from None
    except (FileNotFoundError, GoalError) as exc:
        raise fail(str(exc)) from None
    except Unreachable as exc:
        raise fail(f"unreachable: {exc.reason}") from None
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
        print_problems(exc.problems, exc.source or model)
        raise fail("the model has errors") from None
    except FileNotFoundError as exc:
        raise fail(str(exc)) from None
    simulator = Simulator(loaded)
    console.print(
        f"[bold]{loaded.appliance.name or loaded.appliance.id}[/bold] — "
        "type an action (`help`, `state`, `reset`, `quit`)"
    )
    console.print(f"display: [cyan]{simulator.observe().display!r}[/cyan]")
    try:
        lines = script.read_text(encoding="utf-8").splitlines() if script else None
    except (OSError, UnicodeDecodeError) as exc:
        raise fail(f"cannot read the script {script}: {exc}") from None
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
