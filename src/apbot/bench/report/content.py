"""What the report says, in both formats: the reading guide, table cells, facts and reasons."""

from __future__ import annotations

import html
import json
from collections.abc import Mapping
from typing import Any

from apbot.agent.episode import MAX_REASONING_STEPS
from apbot.bench import plots
from apbot.bench.records import TaskRecord
from apbot.bench.report.snapshot import FaultStudy, Metrics, RunData

REASON_CHARS = 160


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


def category_label(name: str) -> str:
    """``bottle_washer`` → ``Bottle washer``."""
    return name.replace("_", " ").capitalize()


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


def _task_count(data: RunData) -> int:
    counts = [m.overall.n for m in data.summary.methods.values()]
    return max(counts, default=0)


def _belief(data: RunData) -> str:
    return data.summary.belief or str(data.run.get("belief", "")) or "unknown"


def failure_reason(record: TaskRecord) -> str:
    """Why a task failed, in one line."""
    if record.success:
        return ""
    if record.failure:
        reason = record.failure
    elif record.reasoning_steps > MAX_REASONING_STEPS:
        reason = f"over the limit of {MAX_REASONING_STEPS} reasoning steps"
    elif record.claimed_success:
        reason = "claimed success, but the goal does not hold in the true final state"
    else:
        reason = "stopped without reaching the goal"
    reason = " ".join(reason.split())
    return reason if len(reason) <= REASON_CHARS else reason[: REASON_CHARS - 1] + "…"


def value_text(value: Any) -> str:
    """A goal/trace value as plain text (strings bare, numbers short, the rest as JSON).

    >>> value_text("Eco"), value_text(2.50), value_text([1, "a"]), value_text(None)
    ('Eco', '2.5', '[1, "a"]', 'null')
    """
    if isinstance(value, str):
        return value
    if isinstance(value, bool) or value is None:
        return json.dumps(value)
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, int):
        return str(value)
    return json.dumps(value, ensure_ascii=False, sort_keys=True, default=str)


def assignments(values: Mapping[str, Any]) -> str:
    return ", ".join(f"{k}={value_text(v)}" for k, v in values.items())


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
            (f"{sr:.2f} / {spl:.2f}", False) for sr, spl in zip(series.sr, series.spl, strict=True)
        ]
        rows.append(row)
    return ["Method", *(f"rate {r:g}" for r in study.rates)], rows


def header_facts(data: RunData, generated: str) -> list[tuple[str, str]]:
    facts = [("Suite", str(data.run.get("suite", "unknown"))), ("Belief", _belief(data))]
    if "seed" in data.run:
        facts.append(("Seed", str(data.run["seed"])))
    facts += [
        ("Methods", ", ".join(data.methods) or "none"),
        ("Tasks per method", str(_task_count(data))),
        ("Records", str(len(data.records))),
        ("Run", data.run_date),
        ("Report generated", generated),
    ]
    return facts


def esc(value: Any) -> str:
    """Anything as HTML text (quotes too, so it is safe in attributes)."""
    return html.escape(str(value), quote=True)
