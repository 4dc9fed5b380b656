"""The offline reader on manuals written again in the commercial style: styled vs original.

    python benchmarks/styled_reader.py [--appliances bread_maker_4,kettle_1] [--json]
        [--e2e [--methods apbot] [--workers 1] [--out runs/styled] [--sample N]]

``benchmarks/data/styled/<appliance_id>.md`` holds a bundled appliance's manual rewritten the
way a manufacturer's manual reads after PDF-to-text conversion (see the README there); the
appliance's model, panel and tasks are unchanged. It is a DEVELOPMENT set of the nine original
categories — the six held-out categories stay the test. For each styled manual this reads it
with the offline reader and scores it against the true model exactly as ``apbot eval-reader``
does (:func:`apbot.read.evaluate.evaluate`), next to the same appliance's original manual, and
prints precision / recall of variables, discrete values, numeric ranges, placements and
features per appliance and over all of them (``--json``: the same figures as JSON).

``--e2e`` also runs the benchmark's defaults (belief read from the manual, goal read from the
instruction, display feedback; success judged on the true simulator) on each appliance's tasks
twice: from a copy of the suite whose manual is the styled one, and from the bundled suite,
and prints SR / SPL styled vs original. The run directories under ``--out`` are kept, so a
second call resumes.
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
from collections import defaultdict
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from apbot.bench.records import TaskRecord
from apbot.bench.runner import BenchOptions, run_benchmark
from apbot.bench.suite import SuiteAppliance, load_suite
from apbot.read.evaluate import Score, SuiteScore, evaluate

STYLED_DIR = Path(__file__).resolve().parent / "data" / "styled"
METRICS = ("variables", "discrete_values", "numeric_ranges", "placements", "features")
SHORT = {
    "variables": "vars",
    "discrete_values": "discrete",
    "numeric_ranges": "ranges",
    "placements": "placements",
    "features": "features",
}
HELD_OUT = (
    "air_conditioner",
    "blender",
    "coffee_machine",
    "dishwasher",
    "slow_cooker",
    "toaster_oven",
)


class StyledSetError(ValueError):
    """The styled set names an appliance the suite lacks, or one of the held-out categories."""


def styled_manuals(directory: Path = STYLED_DIR) -> dict[str, str]:
    """Every styled manual by appliance id (the file name), README.md left out."""
    if not directory.is_dir():
        raise StyledSetError(f"no styled manuals: {directory} is not a directory")
    return {
        path.stem: path.read_text(encoding="utf-8")
        for path in sorted(directory.glob("*.md"))
        if path.name != "README.md"
    }


def pick(
    manuals: dict[str, str], wanted: Iterable[str] | None, suite_name: str = "bundled"
) -> list[tuple[SuiteAppliance, str]]:
    """The bundled appliances with their styled manual; a clear error for a bad id."""
    suite = load_suite(suite_name)
    ids = list(wanted) if wanted else list(manuals)
    out = []
    for appliance_id in ids:
        if appliance_id not in manuals:
            raise StyledSetError(
                f"no styled manual for {appliance_id!r} in {STYLED_DIR} "
                f"(there are: {', '.join(manuals)})"
            )
        try:
            appliance = suite.get(appliance_id)
        except KeyError as error:
            raise StyledSetError(f"styled manual {appliance_id}.md: {error.args[0]}") from None
        if appliance.category in HELD_OUT:
            raise StyledSetError(
                f"styled manual {appliance_id}.md is of a held-out category "
                f"({appliance.category}); the held-out six stay the test set"
            )
        out.append((appliance, manuals[appliance_id]))
    return out


def score(chosen: list[tuple[SuiteAppliance, str]]) -> tuple[SuiteScore, SuiteScore]:
    """The styled and the original readings scored per appliance (keyed by id) and overall."""
    styled = evaluate((a.id, text, list(a.model.actions), a.model) for a, text in chosen)
    original = evaluate((a.id, a.manual, list(a.model.actions), a.model) for a, _ in chosen)
    return styled, original


def _cell(score: Score, metric: str) -> str:
    counts = getattr(score, metric)
    return f"{counts.precision:.2f}/{counts.recall:.2f}"


def render(
    chosen: list[tuple[SuiteAppliance, str]], styled: SuiteScore, original: SuiteScore
) -> str:
    """One block per appliance (styled row, original row) and the overall block."""
    head = f"{'':<20}{'manual':<10}{'words':>6}" + "".join(f"{SHORT[m]:>12}" for m in METRICS)
    lines = ["precision/recall, offline reader vs the true model (as apbot eval-reader)", head]
    for appliance, text in chosen:
        for label, result, words in (
            ("styled", styled.per_category[appliance.id], len(text.split())),
            ("original", original.per_category[appliance.id], appliance.manual_words),
        ):
            name = appliance.id if label == "styled" else ""
            lines.append(
                f"{name:<20}{label:<10}{words:>6}"
                + "".join(f"{_cell(result, m):>12}" for m in METRICS)
            )
    for label, result in (("styled", styled.overall), ("original", original.overall)):
        name = f"all {len(chosen)}" if label == "styled" else ""
        lines.append(
            f"{name:<20}{label:<10}{'':>6}" + "".join(f"{_cell(result, m):>12}" for m in METRICS)
        )
    lines.append(f"reading time: styled {styled.seconds:.2f} s, original {original.seconds:.2f} s")
    return "\n".join(lines)


def as_json(
    chosen: list[tuple[SuiteAppliance, str]], styled: SuiteScore, original: SuiteScore
) -> dict[str, Any]:
    return {
        "appliances": {
            a.id: {
                "category": a.category,
                "words": {"styled": len(text.split()), "original": a.manual_words},
                "styled": styled.per_category[a.id].table(),
                "original": original.per_category[a.id].table(),
            }
            for a, text in chosen
        },
        "overall": {"styled": styled.overall.table(), "original": original.overall.table()},
        "seconds": {"styled": round(styled.seconds, 3), "original": round(original.seconds, 3)},
    }


def styled_suite(chosen: list[tuple[SuiteAppliance, str]], directory: Path) -> Path:
    """A suite directory of the chosen appliances whose manual is the styled one."""
    for appliance, text in chosen:
        target = directory / appliance.id
        target.mkdir(parents=True, exist_ok=True)
        for name in ("model.yaml", "panel.yaml", "tasks.yaml"):
            shutil.copyfile(appliance.directory / name, target / name)
        (target / "manual.md").write_text(text, encoding="utf-8")
    return directory


def end_to_end(
    chosen: list[tuple[SuiteAppliance, str]],
    methods: list[str],
    out: Path,
    workers: int,
    sample: int | None,
) -> dict[str, list[TaskRecord]]:
    """The benchmark's defaults (read belief, read goal, display) on the styled and original."""
    ids = [a.id for a, _ in chosen]
    suites = {"styled": str(styled_suite(chosen, out / "suite-styled")), "original": "bundled"}
    records: dict[str, list[TaskRecord]] = {}
    for label, suite in suites.items():
        outcome = run_benchmark(
            BenchOptions(
                suite=suite,
                methods=methods,
                appliances=ids,
                workers=workers,
                out=out / label,
                sample=sample,
            ),
            progress=False,
        )
        if outcome.interrupted:
            raise SystemExit(f"the {label} run stopped early ({outcome.stopped_by}); run again")
        records[label] = outcome.records
    return records


def _sr_spl(records: list[TaskRecord]) -> dict[str, float | int]:
    if not records:
        return {"sr": 0.0, "spl": 0.0, "n": 0, "goal_exact": 0}
    return {
        "sr": round(sum(r.success for r in records) / len(records), 3),
        "spl": round(sum(r.spl for r in records) / len(records), 3),
        "n": len(records),
        "goal_exact": sum(1 for r in records if r.goal_exact),
    }


def e2e_figures(records: dict[str, list[TaskRecord]]) -> dict[str, Any]:
    """SR / SPL per method, per appliance and overall, styled and original."""
    by: dict[tuple[str, str, str], list[TaskRecord]] = defaultdict(list)
    for label, recs in records.items():
        for r in recs:
            by[label, r.method, r.appliance].append(r)
            by[label, r.method, "overall"].append(r)
    out: dict[str, Any] = {}
    for label, method, row in sorted(by):
        out.setdefault(method, {}).setdefault(row, {})[label] = _sr_spl(by[label, method, row])
    return out


def render_e2e(figures: dict[str, Any]) -> str:
    lines = ["SR / SPL (goals read = stored), belief read, goal read, display feedback"]
    for method, rows in figures.items():
        lines.append(f"{method:<20}{'styled':>24}{'original':>24}")
        order = [*sorted(r for r in rows if r != "overall"), "overall"]
        for row in order:
            cells = []
            for label in ("styled", "original"):
                f = rows[row].get(label)
                cells.append(
                    f"{f['sr']:.3f} / {f['spl']:.3f} ({f['goal_exact']}/{f['n']})" if f else "–"
                )
            lines.append(f"{row:<20}" + "".join(f"{c:>24}" for c in cells))
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> dict[str, Any]:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--appliances", default=None, help="comma-separated ids (default: all)")
    parser.add_argument("--json", action="store_true", help="print JSON")
    parser.add_argument("--e2e", action="store_true", help="also run the tasks end to end")
    parser.add_argument("--methods", default="apbot")
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--out", default="runs/styled")
    parser.add_argument("--sample", type=int, default=None, help="first N tasks per appliance")
    args = parser.parse_args(argv)
    wanted = [a for a in args.appliances.split(",") if a] if args.appliances else None
    try:
        chosen = pick(styled_manuals(), wanted)
    except StyledSetError as error:
        print(f"error: {error}", file=sys.stderr)
        raise SystemExit(2) from None
    styled, original = score(chosen)
    result = as_json(chosen, styled, original)
    text = render(chosen, styled, original)
    if args.e2e:
        figures = e2e_figures(
            end_to_end(chosen, args.methods.split(","), Path(args.out), args.workers, args.sample)
        )
        result["e2e"] = figures
        text += "\n\n" + render_e2e(figures)
    print(json.dumps(result, indent=2) if args.json else text)
    return result


if __name__ == "__main__":
    main()
