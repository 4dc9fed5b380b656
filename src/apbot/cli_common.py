"""What the command modules share: the consoles, one-line failures, problem listings, and
loading a model or bundled appliance by the name a user typed (with a clear error).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console

from apbot.model.problems import ModelError, Problem
from apbot.model.schema import ApplianceModel

if TYPE_CHECKING:
    from apbot.agent.environment import FeedbackMode
    from apbot.bench.suite import Suite, SuiteAppliance

console = Console(highlight=False, soft_wrap=True)
errors = Console(stderr=True, highlight=False, soft_wrap=True)

ModelArg = Annotated[
    str,
    typer.Argument(
        help="A model file, an appliance directory, an example name or a bundled appliance id."
    ),
]


def fail(message: str, code: int = 1) -> typer.Exit:
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


def print_problems(problems: list[Problem], source: str, stream: Console | None = None) -> None:
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


def chosen_appliances(appliances: list[str] | None) -> list[SuiteAppliance]:
    """The named bundled appliances (loading only those), or the whole suite.

    Exits with a clear message for an unknown id or a broken appliance directory.
    """
    if not appliances:
        return checked_suite().appliances
    return [bundled_appliance(name) for name in appliances]


def bundled_appliance(appliance_id: str, code: int = 1) -> SuiteAppliance:
    """One bundled appliance, loaded and checked alone (not the whole suite: ``apbot run``
    needs one of 45); an unknown id names the closest one."""
    from apbot.bench.suite import bundled_suite_dir, load_appliance
    from apbot.model.values import closest_matches

    ids = sorted(p.name for p in bundled_suite_dir().iterdir() if (p / "model.yaml").exists())
    if appliance_id not in ids:  # a name, never a path
        close = closest_matches(appliance_id, ids, limit=1)
        hint = f"; did you mean {close[0]!r}?" if close else " (see `apbot suite list`)"
        raise fail(f"no appliance {appliance_id!r} in the bundled suite{hint}", code)
    directory = bundled_suite_dir() / appliance_id
    try:
        return load_appliance(directory, check=True)
    except ModelError as exc:
        print_problems(exc.problems, exc.source or appliance_id)
        raise fail(f"{appliance_id} cannot be loaded", code) from None


def checked_suite() -> Suite:
    """The bundled suite, or a clear error naming the broken appliance files."""
    from apbot.bench.suite import load_suite

    try:
        return load_suite(check=True)
    except ModelError as exc:
        print_problems(exc.problems, exc.source or "suite")
        raise fail("the bundled suite cannot be loaded") from None


def split_names(text: str | None) -> list[str] | None:
    """``"a, b,"`` -> ``["a", "b"]``; None when not given."""
    if text is None:
        return None
    return [part.strip() for part in text.split(",") if part.strip()]


def feedback_mode(text: str) -> FeedbackMode:
    """A ``--feedback`` value, checked (typer's Enum choices would print as classes)."""
    from apbot.agent.environment import FEEDBACK_MODES

    for mode in FEEDBACK_MODES:
        if text == mode:
            return mode
    raise fail(f"--feedback must be one of {', '.join(FEEDBACK_MODES)} (got {text!r})", 2)
