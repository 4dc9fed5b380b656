"""``apbot render`` and ``ground``: draw an appliance's panel, and score grounding and
display reading from rendered photos."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from apbot.cli_common import bundled_appliance, console, fail, split_names
from apbot.model.problems import ModelError

if TYPE_CHECKING:
    pass


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

    found = bundled_appliance(appliance)
    if style not in (None, "dot", "seg"):
        raise fail(f"--style must be dot or seg (got {style!r})", 2)
    try:
        chosen_style: Any = style
        text = render_state(found, dict(_pairs(state or [])), out, level, seed, chosen_style)
    except (ValueError, KeyError) as exc:
        raise fail(str(exc), 2) from None
    console.print(f"{out}: {found.id}, display {text!r}", markup=False)


def _pairs(items: list[str]) -> list[tuple[str, str]]:
    pairs = []
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise fail(f"--state wants VAR=VALUE (got {item!r})", 2)
        pairs.append((name.strip(), value.strip()))
    return pairs


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
        raise fail(str(exc)) from None
    wanted = set(split_names(appliances) or [])
    chosen = [a for a in loaded.appliances if not wanted or a.id in wanted]
    if not chosen:
        raise fail(f"no appliances match {sorted(wanted)}")
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
