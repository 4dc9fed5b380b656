"""The fault study: how success and SPL fall as the belief model gets more wrong.

One benchmark runs per (fault rate, seed) into ``OUT/rate-R-seed-S/`` with the belief
``faulty:R`` (so each is resumable, as every benchmark run is); the figures are averaged over
the seeds and written to ``OUT/fault_study.json``::

    {"rates": [0.0, 0.1, ...], "seeds": [0, 1, 2],
     "methods": {METHOD: {"sr": [...], "spl": [...], "reasoning_steps": [...],
                          "execution_steps": [...], "n": [...]}}}

with one entry per rate in each list (``n``: task runs behind it, over all seeds; a figure is
null when no run of the method finished), and drawn in ``OUT/fault_study.png``: SR and SPL
against the fault rate, one line per method.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Sequence
from pathlib import Path
from statistics import fmean
from typing import Any

from matplotlib.figure import Figure

from apbot.bench.plots import png_bytes

DEFAULT_METHODS = ("apbot", "apbot-open-loop")
FIGURES = ("sr", "spl", "reasoning_steps", "execution_steps")
STUDY_FILE = "fault_study.json"
PLOT_FILE = "fault_study.png"


class FaultStudyInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped a run; every finished task is kept and the same call resumes."""


def run_directory(out: Path, rate: float, seed: int) -> Path:
    """Where the run for one (rate, seed) lives, e.g. ``OUT/rate-0.1-seed-0``."""
    return Path(out) / f"rate-{rate:g}-seed-{seed}"


def _check(rates: Sequence[float], methods: Sequence[str], seeds: Sequence[int]) -> None:
    if not rates:
        raise ValueError("give at least one fault rate")
    bad = [r for r in rates if not (math.isfinite(r) and 0.0 <= r <= 1.0)]
    if bad:
        raise ValueError(f"fault rate(s) {', '.join(f'{r:g}' for r in bad)} outside 0..1")
    if len(set(rates)) != len(rates):
        raise ValueError("a fault rate is given twice")
    if not seeds:
        raise ValueError("give at least one seed")
    if len(set(seeds)) != len(seeds):
        raise ValueError("a seed is given twice")
    if not methods:
        raise ValueError("give at least one method")
    from apbot.agent.registry import methods as known

    unknown = [m for m in methods if m not in known()]
    if unknown:
        raise ValueError(f"unknown method(s) {', '.join(unknown)}; known: {', '.join(known())}")


def run_fault_study(
    rates: Sequence[float],
    methods: Sequence[str] = DEFAULT_METHODS,
    seeds: Sequence[int] = (0,),
    *,
    out: Path,
    workers: int | None = None,
    sample: int | None = None,
    progress: bool = True,
    suite: str = "bundled",
    appliances: list[str] | None = None,
) -> dict[str, Any]:
    """Run the study (resuming what is done), write the JSON and the plot, return the JSON.

    Rates are run and reported in increasing order. ``sample``: only the first N tasks of each
    appliance; ``appliances``: only these; ``workers``: default every core.
    Raises :class:`FaultStudyInterrupted` after Ctrl-C (run it again to resume).
    """
    from apbot.bench.runner import BenchOptions, run_benchmark  # the runner pulls the agent in

    rates, seeds, methods = sorted(rates), list(seeds), list(methods)
    _check(rates, methods, seeds)
    out = Path(out)
    summaries: dict[tuple[float, int], dict[str, Any]] = {}
    for rate in rates:
        for seed in seeds:
            if progress:
                from rich.console import Console

                Console(stderr=True).print(f"[bold]fault rate {rate:g}, seed {seed}[/bold]")
            outcome = run_benchmark(
                BenchOptions(
                    suite=suite,
                    methods=methods,
                    appliances=appliances,
                    sample=sample,
                    workers=workers or os.cpu_count() or 1,
                    out=run_directory(out, rate, seed),
                    belief=f"faulty:{rate:g}",
                    seed=seed,
                ),
                progress=progress,
            )
            if outcome.interrupted:
                raise FaultStudyInterrupted(f"interrupted at fault rate {rate:g}, seed {seed}")
            summaries[rate, seed] = outcome.summary
    study = average(summaries, rates, seeds, methods)
    out.mkdir(parents=True, exist_ok=True)
    (out / STUDY_FILE).write_text(json.dumps(study, indent=2) + "\n", encoding="utf-8")
    (out / PLOT_FILE).write_bytes(png_bytes(study_figure(study)))
    return study


def average(
    summaries: dict[tuple[float, int], dict[str, Any]],
    rates: Sequence[float],
    seeds: Sequence[int],
    methods: Sequence[str],
) -> dict[str, Any]:
    """The study's figures: each run summary's ``overall`` figures, averaged over the seeds.

    Seeds weigh equally (each is one draw of faulty models over the same tasks).
    """
    table: dict[str, dict[str, list[Any]]] = {}
    for method in methods:
        columns: dict[str, list[Any]] = {name: [] for name in (*FIGURES, "n")}
        for rate in rates:
            runs = [
                summaries[rate, seed]["methods"][method]["overall"]
                for seed in seeds
                if method in summaries.get((rate, seed), {}).get("methods", {})
            ]
            runs = [r for r in runs if r.get("n", 0) > 0]
            for name in FIGURES:
                columns[name].append(round(fmean(r[name] for r in runs), 6) if runs else None)
            columns["n"].append(sum(r["n"] for r in runs))
        table[method] = columns
    return {"rates": list(rates), "seeds": list(seeds), "methods": table}


def study_figure(study: dict[str, Any]) -> Figure:
    """Two panels, SR and SPL against the fault rate, one line per method."""
    figure = Figure(figsize=(9, 3.4), layout="constrained")
    axes = figure.subplots(1, 2, sharex=True)
    rates = study["rates"]
    seeds = study["seeds"]
    for ax, (key, title) in zip(axes, (("sr", "Success rate"), ("spl", "SPL")), strict=True):
        for method, columns in study["methods"].items():
            points = [(r, v) for r, v in zip(rates, columns[key], strict=True) if v is not None]
            if points:
                ax.plot(*zip(*points, strict=True), marker="o", label=method)
        ax.set_title(title)
        ax.set_xlabel("fault rate (share of sites faulted)")
        ax.set_ylim(0, 1.05)
        ax.grid(alpha=0.3)
    axes[0].legend(loc="best", fontsize="small")
    figure.suptitle(f"Belief faults (mean over {len(seeds)} seed{'s' * (len(seeds) > 1)})")
    return figure


def study_rows(study: dict[str, Any]) -> list[list[str]]:
    """The study as table rows: method, rate, SR, SPL, reasoning and execution steps, n."""
    rows = []
    for method, columns in study["methods"].items():
        for i, rate in enumerate(study["rates"]):
            cells = [columns[name][i] for name in FIGURES]
            shown = [
                "–" if v is None else f"{v:.3f}" if name in ("sr", "spl") else f"{v:.1f}"
                for name, v in zip(FIGURES, cells, strict=True)
            ]
            rows.append([method, f"{rate:g}", *shown, str(columns["n"][i])])
    return rows
