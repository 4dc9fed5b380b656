"""``apbot goal`` and ``eval-goals``: parse one instruction into a goal, or score the goal
parser on a suite's instructions."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich import box
from rich.table import Table

from apbot.cli_common import (
    ModelArg,
    checked_suite,
    console,
    fail,
    print_problems,
    resolve_model,
    split_names,
)
from apbot.cli_llm import CacheOption, LLMOption
from apbot.cli_llm import setup as llm_setup
from apbot.model.problems import ModelError

if TYPE_CHECKING:
    pass


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
            print_problems(exc.problems, exc.source or model)
        message = str(exc) if isinstance(exc, FileNotFoundError) else "the model is invalid"
        raise fail(message) from None
    beside = Path(source).parent / "manual.md"
    text = ""
    if manual is not None or beside.is_file():
        try:
            text = (manual or beside).read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise fail(f"{manual or beside}: cannot read the manual ({exc})") from None
    try:
        if config is not None:
            from apbot.cli_llm import goal_parser

            goal = goal_parser(config)(belief, instruction, text)
        else:
            goal = parse_instruction(belief, instruction, text)
    except (GoalParseError, ValueError) as exc:
        raise fail(f"cannot read the instruction: {exc}") from None
    if as_json:
        console.print_json(json.dumps(goal))
        return
    if not goal:
        console.print("[yellow]the instruction names no setting of this model[/yellow]")
    for name, value in goal.items():
        console.print(f"{name} = {value}")


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
        loaded = checked_suite() if suite == "bundled" else load_suite(suite)
    except (FileNotFoundError, ModelError) as exc:
        if isinstance(exc, ModelError):
            print_problems(exc.problems, exc.source or suite)
        message = str(exc) if isinstance(exc, FileNotFoundError) else "the suite is invalid"
        raise fail(message) from None
    config = llm_setup(llm, cache)
    parser = None
    if config is not None:
        from apbot.cli_llm import goal_parser

        parser = goal_parser(config)
    score = evaluate_goals(loaded, split_names(categories), split_names(appliances), parser, sample)
    if score.n == 0:
        raise fail("no tasks match the chosen categories and appliances")
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
