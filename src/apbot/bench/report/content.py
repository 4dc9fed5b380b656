"""What the report says in both formats: the reading guide, table cells, facts, progress."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from apbot.agent.episode import MAX_REASONING_STEPS
from apbot.bench import plots
from apbot.bench.report.selection import RUN_FILE
from apbot.bench.report.snapshot import FaultStudy, Metrics, RunData
from apbot.bench.report.text import category_label
from apbot.bench.results import RESULTS_FILE

READING_GUIDE = (
    "Every method gets the same tasks: an instruction and the target values of one or more "
    "settings (the goal). A task counts as a success only if the goal holds in the appliance's "
    "true final state — what the method believes or claims does not count — and the method "
    f"stayed within {MAX_REASONING_STEPS} reasoning steps. SR (success rate) is the share of "
    "tasks that succeeded. A reasoning step is one macro action the method decides on (such "
    "as 'set the timer'); presses made only to explore how a control behaves are not "
    "reasoning steps. An execution step is one physical action — a press, a turn, a hold — "
    "exploration included. Step counts are averaged over all tasks, failures included. SPL "
    "(success weighted by path length) credits each success with optimal ÷ max(optimal, "
    "taken) execution steps, the optimum being the oracle's plan on the true model, so a "
    "success that needed twice the presses counts half and a failure counts zero."
)


TABLE_NOTE = (
    "Categories are ordered by the number of variables a task sets. Best per column "
    "in bold (highest rate, then fewest steps)."
)


REFERENCE_NOTE = " † uses the ground-truth model: a reference, not ranked."


SR_TABLE = ("sr", "reasoning_steps")


SPL_TABLE = ("spl", "execution_steps")


def _cell_metrics(data: RunData, method: str, column: str) -> Metrics | None:
    entry = data.summary.methods.get(method)
    if entry is None:
        return None
    return entry.overall if column == "" else entry.categories.get(column)


def _best(data: RunData, column: str, keys: tuple[str, str]) -> set[str]:
    """The methods with the best cell in a column: highest rate, then fewest steps."""
    scored = {}
    for method in data.methods:
        metrics = _cell_metrics(data, method, column)
        if metrics is not None and method not in data.reference:
            scored[method] = (getattr(metrics, keys[0]), -getattr(metrics, keys[1]))
    if not scored:
        return set()
    top = max(scored.values())
    return {m for m, score in scored.items() if score == top}


def table(data: RunData, keys: tuple[str, str]) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    """Header and rows of (cell text, bold) for one of the paper-style tables."""
    columns = [*data.categories, ""]
    header = ["Method", *(category_label(c) for c in data.categories), "Overall"]
    best = {c: _best(data, c, keys) for c in columns}
    rows = []
    for method in data.methods:
        label = method + (" †" if method in data.reference else "")
        row = [(label, False)]
        for column in columns:
            metrics = _cell_metrics(data, method, column)
            if metrics is None:
                row.append(("—", False))
            else:
                text = f"{getattr(metrics, keys[0]):.2f} / {getattr(metrics, keys[1]):.2f}"
                row.append((text, method in best[column]))
        rows.append(row)
    return header, rows


def pvalue_rows(data: RunData) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    methods = [m for m in data.methods if m in data.summary.methods]
    rows = []
    for a in methods:
        row = [(a, False)]
        for b in methods:
            p = data.summary.pvalues.get(a, {}).get(b, data.summary.pvalues.get(b, {}).get(a))
            if a == b or p is None:
                row.append(("—", False))
            else:
                significant = p < plots.SIGNIFICANT
                row.append((plots.format_p(p) + ("*" if significant else ""), significant))
        rows.append(row)
    return ["", *methods], rows


def goal_rows(data: RunData) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    gv = data.summary.goal_variables
    methods = [m for m in data.methods if gv.get(m)]
    counts = sorted({int(k) for m in methods for k in gv[m]})
    rows = []
    for method in methods:
        row = [(method, False)]
        for count in counts:
            point = gv[method].get(str(count))
            row.append((f"{point.sr:.2f} (n={point.n})" if point else "—", False))
        rows.append(row)
    return ["Method", *(f"{c} variable{'s' if c != 1 else ''}" for c in counts)], rows


def fault_rows(study: FaultStudy) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    rows = []
    for method, series in study.methods.items():
        row = [(method, False)]
        row += [
            (f"{_figure(sr)} / {_figure(spl)}", False)
            for sr, spl in zip(series.sr, series.spl, strict=True)
        ]
        rows.append(row)
    return ["Method", *(f"rate {r:g}" for r in study.rates)], rows


def _figure(value: float | None) -> str:
    return "—" if value is None else f"{value:.2f}"


@dataclass(frozen=True)
class Progress:
    """How far the run got: ``state`` is complete, partial or unknown; ``text`` says it."""

    state: Literal["complete", "partial", "unknown"]
    text: str


def progress(data: RunData) -> Progress:
    """Finished tasks against the run's selection, per method where the counts differ.

    The counts come from the same records as every table, so they cannot disagree with them.
    """
    selection, finished = data.selection, data.finished()
    expected = selection.tasks
    if expected is None or not selection.methods:
        why = f"; {selection.note}, so whether the run is complete is unknown"
        return Progress("unknown", f"{len(data.records)} records" + (why if selection.note else ""))
    counts = [finished[m] for m in selection.methods]
    if max(counts) > expected:  # without the keys, records of an earlier bench look alike
        return Progress(
            "unknown",
            f"{max(counts)} records for a method that selected {expected} tasks: "
            f"{RESULTS_FILE} holds records outside the selection ({selection.note})",
        )
    each = " per method" if len(counts) > 1 else ""
    if min(counts) == expected:
        return Progress("complete", f"all {expected} tasks finished{each}")
    if len(set(counts)) == 1:
        return Progress("partial", f"{counts[0]} of {expected} tasks finished{each}")
    first, *rest = selection.methods
    text = f"{first} {finished[first]} of {expected} tasks finished, " + ", ".join(
        f"{m} {finished[m]} of {expected}" for m in rest
    )
    return Progress("partial", text)


PARTIAL_NOTE = (
    "The bench was interrupted or is still running: the tables and figures cover the "
    "finished tasks only. Run the same `apbot bench` command again to finish it."
)


def header_facts(data: RunData, generated: str) -> list[tuple[str, str]]:
    belief = data.summary.belief or str(data.run.get("belief", "")) or "unknown"
    facts = [("Suite", str(data.run.get("suite", "unknown"))), ("Belief", belief)]
    for key in ("seed", "feedback"):
        if key in data.run:
            facts.append((key.capitalize(), str(data.run[key])))
    state = progress(data)
    finished = state.text
    if data.selection.note and state.state != "unknown":
        finished += f" (count from {RUN_FILE}; {data.selection.note})"
    facts += [
        ("Methods", ", ".join(data.methods) or "none"),
        ("Finished", finished),
        ("Records", str(len(data.records))),
    ]
    if data.outside:
        facts.append(
            (
                "Left out",
                f"{data.outside} record(s) in {RESULTS_FILE} outside this run's selection "
                "(an earlier bench into the same directory)",
            )
        )
    facts += [("Run", data.run_date), ("Report generated", generated)]
    return facts
