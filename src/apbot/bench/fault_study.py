"""The fault study: how success and SPL fall as the belief model gets more wrong, per fault kind.

Two modes, one benchmark per run (each resumable, as every benchmark run is):

- *mixed* (the default): one run per (fault rate, seed) in ``OUT/rate-R-seed-S/`` with the
  belief ``faulty:R`` (every kind, or ``faulty:R:K1,K2`` with ``kinds``);
- *single kind*: for each kind K, one run per (rate, seed) in ``OUT/kind-K/rate-R-seed-S/``
  with the belief ``faulty:R:K``, so each kind is measured on its own — over the appliances
  the kind can hit at that (rate, seed) (:func:`apbot.bench.faults.candidate_sites`).

The figures go to ``OUT/fault_study.json``::

    {"mode": "mixed" | "single-kind", "feedback": "values" | "display",
     "rates": [0.0, 0.1, ...], "seeds": [0, 1, 2], "kinds": [...] | null,
     "methods": {METHOD: {"sr": [...], "spl": [...], "reasoning_steps": [...],
                          "execution_steps": [...], "n": [...], "false_claims": [...]}},
     "per_kind": {METHOD: {KIND: {"sr": [...], "spl": [...], "n": [...],
                                  "false_claims": [...]}}}}

with one entry per rate in each list. ``methods`` holds each run summary's overall figures
averaged over the seeds (seeds weigh equally; ``n``: task runs behind it; a figure is null when
no run of the method finished); ``false_claims`` counts runs that claimed success without
reaching the goal. ``per_kind`` pools the records over the seeds: a record counts for kind K
when its belief has a fault of kind K (a record with several kinds counts for each), plus the
rows ``any`` (a belief with at least one fault) and ``none`` (no fault: the kinds could not hit
that appliance). ``OUT/fault_study.png`` plots SR and SPL against the fault rate.
"""

from __future__ import annotations

import json
import math
import os
from collections import defaultdict
from collections.abc import Iterable, Sequence
from pathlib import Path
from statistics import fmean
from typing import Any

from matplotlib.figure import Figure

from apbot.bench.faults import FAULT_KINDS, candidate_sites, fault_kind
from apbot.bench.plots import png_bytes
from apbot.bench.records import TaskRecord

DEFAULT_METHODS = ("apbot", "apbot-open-loop")
FEEDBACK_MODES = ("display", "values")
FIGURES = ("sr", "spl", "reasoning_steps", "execution_steps")
KIND_FIGURES = ("sr", "spl", "n", "false_claims")
ANY, NONE = "any", "none"  # the per-kind rows for "some fault" and "no fault"
STUDY_FILE = "fault_study.json"
PLOT_FILE = "fault_study.png"


class FaultStudyInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped a run; every finished task is kept and the same call resumes."""


def run_directory(out: Path, rate: float, seed: int, kind: str | None = None) -> Path:
    """Where the run for one (rate, seed) lives, e.g. ``OUT/rate-0.1-seed-0``, or for one
    kind on its own ``OUT/kind-guard/rate-0.1-seed-0``."""
    base = Path(out) if kind is None else Path(out) / f"kind-{kind}"
    return base / f"rate-{rate:g}-seed-{seed}"


def _check(
    rates: Sequence[float],
    methods: Sequence[str],
    seeds: Sequence[int],
    feedback: str,
    kinds: Sequence[str] | None,
) -> None:
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
    if feedback not in FEEDBACK_MODES:
        raise ValueError(f"unknown feedback mode {feedback!r}; known: {', '.join(FEEDBACK_MODES)}")
    if kinds is not None:
        wrong = [k for k in kinds if k not in FAULT_KINDS]
        if wrong or not kinds:
            raise ValueError(
                f"unknown fault kind(s) {', '.join(wrong) or '(none given)'}; "
                f"known: {', '.join(FAULT_KINDS)}"
            )


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
    feedback: str = "display",
    single_kind: bool = False,
    kinds: Sequence[str] | None = None,
) -> dict[str, Any]:
    """Run the study (resuming what is done), write the JSON and the plot, return the JSON.

    Rates are run and reported in increasing order. ``sample``: only the first N tasks of each
    appliance; ``appliances``: only these; ``workers``: default every core; ``feedback``: what
    the methods perceive (``BenchOptions.feedback``); ``kinds``: the fault kinds injected
    (mixed) or measured one by one (``single_kind``); default every kind.
    Raises :class:`FaultStudyInterrupted` after Ctrl-C (run it again to resume).
    """
    from apbot.bench.runner import BenchOptions, cached_suite, run_benchmark

    rates, seeds, methods = sorted(rates), list(seeds), list(methods)
    _check(rates, methods, seeds, feedback, kinds)
    chosen = [k for k in FAULT_KINDS if kinds is None or k in kinds]
    out = Path(out)
    summaries: dict[tuple[float, int], dict[str, Any]] = {}
    records: dict[float, list[TaskRecord]] = defaultdict(list)
    runs: list[tuple[float, int, str | None]] = [
        (rate, seed, kind)
        for kind in (chosen if single_kind else [None])
        for rate in rates
        for seed in seeds
    ]
    for rate, seed, kind in runs:
        belief = f"faulty:{rate:g}"
        if kind is not None:
            belief += f":{kind}"
        elif kinds is not None:
            belief += f":{','.join(chosen)}"
        selected = appliances
        if kind is not None:
            selected = _hit(cached_suite(suite), appliances, rate, seed, kind)
            if not selected:
                continue
        if progress:
            from rich.console import Console

            Console(stderr=True).print(f"[bold]belief {belief}, seed {seed}[/bold]")
        outcome = run_benchmark(
            BenchOptions(
                suite=suite,
                methods=methods,
                appliances=selected,
                sample=sample,
                workers=workers or os.cpu_count() or 1,
                out=run_directory(out, rate, seed, kind),
                belief=belief,
                seed=seed,
                feedback=feedback,  # type: ignore[arg-type]
                goal="given",  # the study measures model faults: the stored goal, as before
            ),
            progress=progress,
        )
        if outcome.interrupted:
            raise FaultStudyInterrupted(f"interrupted at belief {belief}, seed {seed}")
        records[rate] += outcome.records
        if kind is None:
            summaries[rate, seed] = outcome.summary
    if single_kind:
        study = _pooled_study(records, rates, seeds, methods)
    else:
        study = average(summaries, rates, seeds, methods)
        for method in methods:
            study["methods"][method]["false_claims"] = [
                false_claims(r for r in records[rate] if r.method == method) for rate in rates
            ]
    study = {
        "mode": "single-kind" if single_kind else "mixed",
        "feedback": feedback,
        **study,
        "kinds": None if kinds is None else chosen,
        "per_kind": per_kind(records, rates, methods, only=chosen if single_kind else None),
    }
    out.mkdir(parents=True, exist_ok=True)
    (out / STUDY_FILE).write_text(json.dumps(study, indent=2) + "\n", encoding="utf-8")
    (out / PLOT_FILE).write_bytes(png_bytes(study_figure(study)))
    return study


def _hit(suite: Any, appliances: list[str] | None, rate: float, seed: int, kind: str) -> list[str]:
    """The appliances (of the selection) that ``kind`` can fault at this rate and seed."""
    return [
        a.id
        for a in suite.appliances
        if (appliances is None or a.id in appliances)
        and candidate_sites(a.model, rate, f"{seed}/{a.id}", [kind])
    ]


def false_claims(records: Iterable[TaskRecord]) -> int:
    """Runs that claimed success but did not reach the goal (the issue demands none)."""
    return sum(r.claimed_success and not r.success for r in records)


def record_kinds(record: TaskRecord) -> set[str]:
    """The kinds of fault in a record's belief (``TaskRecord.faults`` are ``"KIND target: …"``)."""
    return {fault_kind(text) for text in record.faults}


def kind_figures(records: Sequence[TaskRecord]) -> dict[str, Any]:
    """SR, mean SPL, the number of runs and of false success claims (null figures when empty)."""
    if not records:
        return {"sr": None, "spl": None, "n": 0, "false_claims": 0}
    return {
        "sr": round(fmean(r.success for r in records), 6),
        "spl": round(fmean(r.spl for r in records), 6),
        "n": len(records),
        "false_claims": false_claims(records),
    }


def per_kind(
    records: dict[float, list[TaskRecord]],
    rates: Sequence[float],
    methods: Sequence[str],
    only: Sequence[str] | None = None,
) -> dict[str, dict[str, dict[str, list[Any]]]]:
    """``{method: {kind: {sr, spl, n, false_claims: [one per rate]}}}`` (module doc), for the
    kinds that occur (or ``only`` these), in ``FAULT_KINDS`` order, then ``any`` and ``none``."""
    table: dict[str, dict[str, dict[str, list[Any]]]] = {}
    for method in methods:
        rows: dict[str, dict[str, list[Any]]] = {}
        mine = {rate: [r for r in records.get(rate, []) if r.method == method] for rate in rates}
        present = {k for group in mine.values() for r in group for k in record_kinds(r)}
        for kind in [*(k for k in FAULT_KINDS if k in (only or present)), ANY, NONE]:
            columns: dict[str, list[Any]] = {name: [] for name in KIND_FIGURES}
            for rate in rates:
                group = [r for r in mine[rate] if _counts_for(r, kind)]
                for name, number in kind_figures(group).items():
                    columns[name].append(number)
            rows[kind] = columns
        table[method] = rows
    return table


def _counts_for(record: TaskRecord, kind: str) -> bool:
    if kind == ANY:
        return bool(record.faults)
    if kind == NONE:
        return not record.faults
    return kind in record_kinds(record)


def _pooled_study(
    records: dict[float, list[TaskRecord]],
    rates: Sequence[float],
    seeds: Sequence[int],
    methods: Sequence[str],
) -> dict[str, Any]:
    """Single-kind mode: per method and rate, the figures over every kind's runs that had a
    fault (the runs of appliances a kind could not hit are not in the study)."""
    from apbot.bench.metrics import figures

    table: dict[str, dict[str, list[Any]]] = {}
    for method in methods:
        columns: dict[str, list[Any]] = {name: [] for name in (*FIGURES, "n", "false_claims")}
        for rate in rates:
            group = [r for r in records.get(rate, []) if r.method == method and r.faults]
            found = figures(group)
            for name in FIGURES:
                columns[name].append(found[name] if group else None)
            columns["n"].append(len(group))
            columns["false_claims"].append(false_claims(group))
        table[method] = columns
    return {"rates": list(rates), "seeds": list(seeds), "methods": table}


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
    where = f", {study['feedback']} feedback" if study.get("feedback") else ""
    figure.suptitle(f"Belief faults (mean over {len(seeds)} seed{'s' * (len(seeds) > 1)}{where})")
    return figure


def _cell(value: Any, name: str) -> str:
    if value is None:
        return "–"
    return f"{value:.3f}" if name in ("sr", "spl") else f"{value:.1f}"


def study_rows(study: dict[str, Any]) -> list[list[str]]:
    """The study as table rows: method, rate, SR, SPL, reasoning and execution steps, n."""
    rows = []
    for method, columns in study["methods"].items():
        for i, rate in enumerate(study["rates"]):
            shown = [_cell(columns[name][i], name) for name in FIGURES]
            rows.append([method, f"{rate:g}", *shown, str(columns["n"][i])])
    return rows


def kind_rows(
    table: dict[str, dict[str, dict[str, list[Any]]]], rates: Sequence[float]
) -> list[list[str]]:
    """The per-kind table as rows: kind, method, rate, n, SR, SPL, false claims — the methods
    of one kind side by side."""
    kinds = list(dict.fromkeys(kind for rows in table.values() for kind in rows))
    out = []
    for kind in kinds:
        for method, rows in table.items():
            if kind not in rows:
                continue
            columns = rows[kind]
            for i, rate in enumerate(rates):
                out.append(
                    [
                        kind,
                        method,
                        f"{rate:g}",
                        str(columns["n"][i]),
                        _cell(columns["sr"][i], "sr"),
                        _cell(columns["spl"][i], "spl"),
                        str(columns["false_claims"][i]),
                    ]
                )
    return out


def directory_table(directory: Path) -> tuple[list[float], dict[str, Any]]:
    """The per-kind table of one run directory, or of every run under a study directory
    (records pooled per fault rate, read from ``results.jsonl`` files, never written)."""
    from apbot.bench.beliefs import parse_belief
    from apbot.bench.results import RESULTS_FILE, read_records

    directory = Path(directory)
    runs = sorted({p.parent for p in directory.rglob(RESULTS_FILE)})
    if not runs:
        raise ValueError(f"{directory} holds no {RESULTS_FILE} (not a run or study directory)")
    records: dict[float, list[TaskRecord]] = defaultdict(list)
    for run in runs:
        for record in read_records(run):
            spec = parse_belief(record.belief)
            records[spec.rate] += [record]
    rates = sorted(records)
    methods = list(dict.fromkeys(r.method for group in records.values() for r in group))
    return rates, per_kind(records, rates, methods)
