"""The defaults end to end on manuals made noisy the way real commercial manuals are.

    python benchmarks/manual_noise.py [--categories a,b | --appliances a_1,b_2]
        [--kinds boilerplate,pages,wraps,tables,sister,all] [--workers 1] [--out runs/noise]
        [--sample N] [--seed 0]

Real manuals run up to 40,000 characters, flattened by a vision model, with safety, cleaning,
guarantee and disposal text, page headers and footers, hard-wrapped hyphenated lines, tables
drawn with spaces and paragraphs for other models of the range. For each perturbation (see
``noise_perturb.py``; each alone, and ``all`` together) this writes a copy of the suite whose
manuals are perturbed (model, panel and tasks unchanged) and runs ``apbot bench``'s defaults
(belief read, goal read, display feedback, method ``apbot``) on it and on the clean suite, and
prints SR / SPL per perturbation next to clean, per category and overall, and how many goals
read are the stored one. Default: the nine development categories. Run directories under
``--out`` are kept, so a second call resumes.
"""

from __future__ import annotations

import argparse
import shutil
import sys
from collections import defaultdict
from pathlib import Path

from apbot.bench.records import TaskRecord
from apbot.bench.runner import BenchOptions, run_benchmark
from apbot.bench.suite import READER_DEVELOPMENT_CATEGORIES, SuiteAppliance, load_suite

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from benchmarks.noise_perturb import KINDS, perturb

NINE = READER_DEVELOPMENT_CATEGORIES


def noisy_suite(
    appliances: list[SuiteAppliance], kind: str, directory: Path, seed: int = 0
) -> Path:
    """A suite directory of the appliances whose manual carries perturbation ``kind``."""
    for appliance in appliances:
        target = directory / appliance.id
        target.mkdir(parents=True, exist_ok=True)
        for name in ("model.yaml", "panel.yaml", "tasks.yaml"):
            shutil.copyfile(appliance.directory / name, target / name)
        text = perturb(appliance.manual, kind, appliance.id, seed)
        (target / appliance.manual_file).write_text(text, encoding="utf-8")
    return directory


def _figures(records: list[TaskRecord]) -> str:
    if not records:
        return "–"
    sr = sum(r.success for r in records) / len(records)
    spl = sum(r.spl for r in records) / len(records)
    return f"{sr:.3f}/{spl:.3f}"


def render(records: dict[str, list[TaskRecord]], chars: dict[str, int]) -> str:
    """SR/SPL per category (rows) and perturbation (columns), the overall row, goals read."""
    labels = list(records)
    by: dict[tuple[str, str], list[TaskRecord]] = defaultdict(list)
    for label, recs in records.items():
        for r in recs:
            by[label, r.category].append(r)
            by[label, "overall"].append(r)
    categories = sorted({r.category for recs in records.values() for r in recs})
    lines = ["SR/SPL, method apbot, belief read, goal read, display feedback"]
    lines.append(f"{'':<18}" + "".join(f"{label:>13}" for label in labels))
    for row in [*categories, "overall"]:
        lines.append(f"{row:<18}" + "".join(f"{_figures(by[lb, row]):>13}" for lb in labels))
    clean = by["clean", "overall"] if "clean" in records else []
    base = sum(r.success for r in clean) / len(clean) if clean else 0.0
    delta = []
    for label in labels:
        recs = by[label, "overall"]
        sr = sum(r.success for r in recs) / len(recs) if recs else 0.0
        delta.append(f"{sr - base:+.3f}")
    lines.append(f"{'SR vs clean':<18}" + "".join(f"{d:>13}" for d in delta))
    goals = [f"{sum(r.goal_exact for r in records[lb])}/{len(records[lb])}" for lb in labels]
    lines.append(f"{'goals = stored':<18}" + "".join(f"{g:>13}" for g in goals))
    lines.append(f"{'mean chars':<18}" + "".join(f"{chars[lb]:>13,}" for lb in labels))
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> dict[str, list[TaskRecord]]:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--categories", default=",".join(NINE), help="comma-separated")
    parser.add_argument(
        "--appliances", default=None, help="comma-separated ids (over --categories)"
    )
    parser.add_argument("--kinds", default=",".join(KINDS), help="perturbations to run")
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--out", default="runs/noise")
    parser.add_argument("--sample", type=int, default=None, help="first N tasks per appliance")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    suite = load_suite("bundled")
    if args.appliances:
        wanted = [a for a in args.appliances.split(",") if a]
        appliances = [suite.get(a) for a in wanted]
    else:
        cats = set(args.categories.split(","))
        appliances = [a for a in suite.appliances if a.category in cats]
    kinds = [k for k in args.kinds.split(",") if k]
    for kind in kinds:
        if kind not in KINDS:
            parser.error(f"unknown perturbation {kind!r} (one of {', '.join(KINDS)})")
    ids = [a.id for a in appliances]
    out = Path(args.out)
    records: dict[str, list[TaskRecord]] = {}
    chars: dict[str, int] = {}
    for label in ["clean", *kinds]:
        if label == "clean":
            where = "bundled"
            sizes = [len(a.manual) for a in appliances]
        else:
            where = str(noisy_suite(appliances, label, out / f"suite-{label}", args.seed))
            sizes = [len(perturb(a.manual, label, a.id, args.seed)) for a in appliances]
        chars[label] = sum(sizes) // max(len(sizes), 1)
        outcome = run_benchmark(
            BenchOptions(
                suite=where,
                methods=["apbot"],
                appliances=ids,
                workers=args.workers,
                out=out / label,
                sample=args.sample,
            ),
            progress=False,
        )
        if outcome.interrupted:
            raise SystemExit(f"the {label} run stopped early ({outcome.stopped_by}); run again")
        records[label] = outcome.records
    print(render(records, chars))
    return records


if __name__ == "__main__":
    main()
