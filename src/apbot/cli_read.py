"""``apbot read`` and ``eval-reader``: read a manual into a model, or score the reader
against the suite's ground truth."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from apbot.cli_common import bundled_appliance, console, fail, split_names
from apbot.cli_llm import CacheOption, LLMOption
from apbot.cli_llm import setup as llm_setup
from apbot.model.problems import ModelError

if TYPE_CHECKING:
    pass


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
    from apbot.model.load import model_to_yaml
    from apbot.model.yaml_text import read_text
    from apbot.read import ReaderError, read_manual
    from apbot.read.commands import action_names

    if (actions is None) == (appliance is None):
        raise fail("give exactly one of --actions FILE or --appliance ID")
    try:
        names = (
            action_names(actions)
            if actions
            else list(bundled_appliance(str(appliance)).model.actions)
        )
        config = llm_setup(llm, cache)
        if config is None:
            reading = read_manual(read_text(manual), names, category=manual.stem)
        else:
            from apbot.cli_llm import read_with_llm

            reading = read_with_llm(config, read_text(manual), names, manual.stem, from_scratch)
    except (ReaderError, OSError, ModelError) as exc:
        raise fail(str(exc)) from None
    text = model_to_yaml(reading.model)
    if out:
        out.write_text(text, encoding="utf-8")
    if as_json:
        console.print_json(json.dumps({"notes": reading.report.to_json()}))
    else:
        console.print(reading.report.render(), markup=False)
        if not out:
            console.print(text, markup=False)


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
        raise fail(str(exc)) from None
    wanted = set(split_names(categories) or [])
    chosen = [a for a in loaded.appliances if not wanted or a.category in wanted]
    if appliances:
        from fnmatch import fnmatchcase

        patterns = split_names(appliances) or []
        chosen = [a for a in chosen if any(fnmatchcase(a.id, p) for p in patterns)]
    if not chosen:
        raise fail(f"no appliances in categories {sorted(wanted)}")
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
