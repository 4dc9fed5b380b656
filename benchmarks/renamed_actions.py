"""The method under other action names: the same appliances, their actions named another way.

    python benchmarks/renamed_actions.py [--suite bundled|DIR] [--appliances a_1,b_1]
        [--style button] [--methods apbot] [--workers 1] [--out runs/renamed] [--json]

An environment names its actions however its author likes: our suites say ``press_menu``,
``hold_lock``, ``turn_dial_cw``; another simulator, or a robot's grounding, may say
``press_menu_button``, ``press_and_hold_lock_button``, ``turn_timer_dial_clockwise`` (the names
the issue that asked for the reader gives). Nothing about the appliance changes with the names,
so neither should the figures: this writes a copy of the suite whose ground-truth models name
every action in the chosen style (the manual, panel and tasks unchanged), reads each manual with
the renamed actions, and prints eval-reader precision / recall and end-to-end SR / SPL (the
benchmark's defaults: read belief, read goal, display feedback) renamed vs original.

Styles (``--style``):
- ``button``: ``press_X_button``, ``press_and_hold_X_button`` (two keys held together:
  ``press_and_hold_X_and_Y_buttons``), ``turn_X_dial_clockwise`` / ``_counterclockwise``;
- ``key``: ``push_X_key``, ``long_press_X_key`` (``long_press_X_and_Y_keys``),
  ``rotate_X_knob_right`` / ``_left``.

Only the nine development categories run by default on the bundled suite (``--appliances`` picks
others); the held-out six stay the test. The run directories under ``--out`` are kept: a second
call resumes.
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import yaml

from apbot.bench.runner import BenchOptions, run_benchmark
from apbot.bench.suite import READER_DEVELOPMENT_CATEGORIES, SuiteAppliance, load_suite
from apbot.read.evaluate import evaluate

TURN_ENDS = ("cw", "ccw", "clockwise", "anticlockwise", "counterclockwise", "left", "right")
STYLES = ("button", "key")
METRICS = ("variables", "discrete_values", "numeric_ranges", "placements", "features")


def renamed(name: str, spec: dict[str, Any], style: str) -> str:
    """``name`` in ``style``, from what the action does (its skill), not from how it is spelled."""
    skill = spec.get("skill", "press")
    if skill == "wait":
        return name
    rest = name.split("_", 1)[1] if "_" in name else name
    if skill in ("turn_cw", "turn_ccw"):
        parts = rest.split("_")
        base = "_".join(parts[:-1]) if parts[-1] in TURN_ENDS else rest
        if style == "button":
            way = "clockwise" if skill == "turn_cw" else "counterclockwise"
            return f"turn_{base}_dial_{way}" if base else f"turn_dial_{way}"
        way = "right" if skill == "turn_cw" else "left"  # turn_cw: the panel's one dial
        return f"rotate_{base}_knob_{way}" if base else f"rotate_dial_{way}"
    two = spec.get("controls") is not None
    if skill == "hold":
        if style == "button":
            return f"press_and_hold_{rest}_buttons" if two else f"press_and_hold_{rest}_button"
        return f"long_press_{rest}_keys" if two else f"long_press_{rest}_key"
    return f"press_{rest}_button" if style == "button" else f"push_{rest}_key"


def rename_map(model: dict[str, Any], style: str) -> dict[str, str]:
    """Every action's new name; raise when two would collide."""
    mapping = {name: renamed(name, spec or {}, style) for name, spec in model["actions"].items()}
    if len(set(mapping.values())) != len(mapping):
        raise ValueError(f"renaming in style {style!r} makes two actions one: {mapping}")
    return mapping


def _replace(node: Any, mapping: dict[str, str]) -> Any:
    """The model data with every action name (as a key or a string) replaced."""
    if isinstance(node, dict):  # a skill is no action name, even where one is spelled alike
        return {
            mapping.get(k, k): v if k == "skill" else _replace(v, mapping) for k, v in node.items()
        }
    if isinstance(node, list):
        return [_replace(v, mapping) for v in node]
    if isinstance(node, str):
        return mapping.get(node, node)
    return node


def renamed_model(model: dict[str, Any], style: str) -> dict[str, Any]:
    """The ground-truth model data with its actions named in ``style``."""
    return _replace(model, rename_map(model, style))


def renamed_suite(appliances: list[SuiteAppliance], style: str, directory: Path) -> Path:
    """A suite directory of the appliances, each model's actions renamed."""
    return rewritten_suite(appliances, lambda _, data: renamed_model(data, style), directory)


def rewritten_suite(
    appliances: list[SuiteAppliance],
    rewrite: Callable[[SuiteAppliance, dict[str, Any]], dict[str, Any]],
    directory: Path,
) -> Path:
    """A suite directory of the appliances, manuals, panels and tasks as they are, each model
    as ``rewrite`` gives it (the appliance, the model's data)."""
    for appliance in appliances:
        target = directory / appliance.id
        target.mkdir(parents=True, exist_ok=True)
        for name in (appliance.manual_file, "panel.yaml", "tasks.yaml"):
            shutil.copyfile(appliance.directory / name, target / name)
        data = yaml.safe_load((appliance.directory / "model.yaml").read_text(encoding="utf-8"))
        text = yaml.safe_dump(rewrite(appliance, data), sort_keys=False, allow_unicode=True)
        (target / "model.yaml").write_text(text, encoding="utf-8")
    return directory


def _reader_figures(suite: str, ids: list[str]) -> dict[str, Any]:
    chosen = [a for a in load_suite(suite).appliances if a.id in ids]
    score = evaluate((a.id, a.manual, list(a.model.actions), a.model) for a in chosen).overall
    return {
        metric: [round(counts.precision, 3), round(counts.recall, 3)]
        for metric in METRICS
        for counts in [getattr(score, metric)]
    }


def e2e_figures(suite: str, ids: list[str], methods: list[str], out: Path, workers: int) -> dict:
    outcome = run_benchmark(
        BenchOptions(suite=suite, methods=methods, appliances=ids, workers=workers, out=out),
        progress=False,
    )
    if outcome.interrupted:
        raise SystemExit(f"the run in {out} stopped early ({outcome.stopped_by}); run again")
    figures: dict[str, Any] = {}
    for method in methods:
        records = [r for r in outcome.records if r.method == method]
        n = max(len(records), 1)
        figures[method] = {
            "sr": round(sum(r.success for r in records) / n, 3),
            "spl": round(sum(r.spl for r in records) / n, 3),
            "n": len(records),
        }
    return figures


def main(argv: list[str] | None = None) -> dict[str, Any]:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--suite", default="bundled")
    parser.add_argument("--appliances", default=None, help="comma-separated ids")
    parser.add_argument("--style", default="button", choices=STYLES)
    parser.add_argument("--methods", default="apbot")
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--out", default="runs/renamed")
    parser.add_argument("--no-e2e", action="store_true", help="the reader's scores only")
    parser.add_argument("--json", action="store_true", help="print JSON")
    args = parser.parse_args(argv)
    suite = load_suite(args.suite)
    wanted = set(args.appliances.split(",")) if args.appliances else None
    chosen = [
        a
        for a in suite.appliances
        if (
            a.id in wanted
            if wanted
            else args.suite != "bundled" or a.category in READER_DEVELOPMENT_CATEGORIES
        )
    ]
    if not chosen:
        print("error: no appliance chosen", file=sys.stderr)
        raise SystemExit(2)
    ids = [a.id for a in chosen]
    out = Path(args.out)
    copy = str(renamed_suite(chosen, args.style, out / f"suite-{args.style}"))
    result: dict[str, Any] = {
        "style": args.style,
        "appliances": len(ids),
        "reader": {
            "renamed": _reader_figures(copy, ids),
            "original": _reader_figures(args.suite, ids),
        },
    }
    if not args.no_e2e:
        methods = args.methods.split(",")
        result["e2e"] = {
            "renamed": e2e_figures(copy, ids, methods, out / args.style, args.workers),
            "original": e2e_figures(args.suite, ids, methods, out / "original", args.workers),
        }
    print(json.dumps(result, indent=2) if args.json else _render(result))
    return result


def _render(result: dict[str, Any]) -> str:
    lines = [f"actions renamed in style {result['style']!r}, {result['appliances']} appliances"]
    lines.append(f"{'reader P / R':<22}{'renamed':>16}{'original':>16}")
    for metric, (p, r) in result["reader"]["renamed"].items():
        p0, r0 = result["reader"]["original"][metric]
        lines.append(f"{metric:<22}{f'{p:.2f} / {r:.2f}':>16}{f'{p0:.2f} / {r0:.2f}':>16}")
    for method, fig in result.get("e2e", {}).get("renamed", {}).items():
        orig = result["e2e"]["original"][method]
        lines.append(
            f"{method + ' SR / SPL':<22}{fig['sr']:>8.3f} / {fig['spl']:.3f}"
            f"{orig['sr']:>8.3f} / {orig['spl']:.3f}  ({fig['n']} tasks)"
        )
    return "\n".join(lines)


if __name__ == "__main__":
    main()
