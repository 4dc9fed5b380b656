"""The traces section: every task of every method, grouped by appliance, failures first.

The list itself is plain HTML, so it reads without JavaScript: per method, one collapsible
group per appliance (those with failures first, and open), and inside a group the failures
before the successes. Opening a task asks ``viewer.js`` to draw its instruction, goal and
trace from the data embedded once at the end of the section (see :mod:`.viewer`); a text
filter and a "failures only" toggle narrow the list.
"""

from __future__ import annotations

import re
from collections import defaultdict

from apbot.bench.records import TaskRecord
from apbot.bench.report.snapshot import RunData
from apbot.bench.report.text import category_label, esc, failure_reason
from apbot.bench.report.viewer import encode, viewer_data

DATA_ID = "viewer-data"
Groups = dict[str, list[tuple[str, list[TaskRecord]]]]

LEGEND = (
    "Per method, one group per appliance: those with failures first (and open), failures "
    "before successes inside. Open a task for its instruction, goal, final values and whole "
    "trace. Rows: macro actions (blue), presses with the display after them, exploration "
    "(grey italics), checks (mismatches marked red), repairs of the model (yellow)."
)


NO_SCRIPT = (
    "Opening a task shows its details and trace once the page's script has run; where it "
    "cannot run, results.jsonl holds them in full."
)


def slug(name: str) -> str:
    return "m-" + re.sub(r"[^A-Za-z0-9_-]", "-", name)


def grouped(data: RunData) -> Groups:
    """Records per method (the run's order) and appliance: appliances with the most failures
    first, then by name; in each, failures before successes, by task id."""
    by_method: dict[str, dict[str, list[TaskRecord]]] = {m: defaultdict(list) for m in data.methods}
    for record in data.records:
        by_method[record.method][record.appliance].append(record)
    groups: Groups = {}
    for method, appliances in by_method.items():
        ordered = sorted(
            appliances.items(), key=lambda item: (-sum(not r.success for r in item[1]), item[0])
        )
        groups[method] = [
            (appliance, sorted(records, key=lambda r: (r.success, r.task, r.key)))
            for appliance, records in ordered
        ]
    return groups


def _count(failed: int, passed: int, missing: int) -> str:
    parts = [f"{failed} failed", f"{passed} succeeded"]
    if missing > 0:
        parts.append(f"{missing} not run yet")
    return ", ".join(parts)


def _task_line(record: TaskRecord, index: int) -> str:
    css = "s" if record.success else "f"
    text = (
        f"{record.task} · R {record.reasoning_steps} · E {record.execution_steps} "
        f"(optimal {record.optimal_steps}) · SPL {record.spl:.2f}"
    )
    repaired = ' <span class="rep">repaired</span>' if record.repairs else ""
    reason = "" if record.success else f" — {esc(failure_reason(record))}"
    return (
        f'<details class="t {css}" data-i="{index}"><summary>{esc(text)}{repaired}{reason}'
        "</summary></details>"
    )


def _method_html(
    data: RunData, method: str, groups: list[tuple[str, list[TaskRecord]]]
) -> list[str]:
    records = [r for _, rs in groups for r in rs]
    failed = sum(not r.success for r in records)
    expected = data.selection.tasks
    missing = expected - len(records) if expected is not None else 0
    out = [
        f'<section class="method" id="{slug(method)}"><h3>{esc(method)}</h3>',
        f'<p class="muted">{_count(failed, len(records) - failed, missing)}</p>',
        '<p class="muted none" hidden>No task of this method matches the filter.</p>',
    ]
    if not records:
        out.append('<p class="muted">No records yet.</p>')
    return out


def traces_html(data: RunData) -> list[str]:
    """The section: legend, filter, per-method groups of tasks, and the viewer's data."""
    groups = grouped(data)
    ordered = [r for method in groups for _, rs in groups[method] for r in rs]
    out = [
        '<h2 id="traces">Traces</h2>',
        f'<p class="muted">{esc(LEGEND)}</p>',
        f'<p id="viewer-status" class="muted">{esc(NO_SCRIPT)}</p>',
        '<div id="filter" class="filter" hidden><input type="search" id="filter-text" '
        'placeholder="Filter: appliance, task, category, instruction, reason" '
        'aria-label="Filter the tasks"> <label><input type="checkbox" id="filter-failures"> '
        'failures only</label> <span id="filter-count" class="muted"></span></div>',
        "<ul>"
        + "".join(
            f'<li><a href="#{slug(m)}">{esc(m)}</a>: '
            f"{sum(not r.success for _, rs in groups[m] for r in rs)} failed, "
            f"{sum(r.success for _, rs in groups[m] for r in rs)} succeeded</li>"
            for m in groups
        )
        + "</ul>",
    ]
    index = 0
    for method, appliance_groups in groups.items():
        out += _method_html(data, method, appliance_groups)
        for appliance, records in appliance_groups:
            failed = sum(not r.success for r in records)
            expected = data.selection.appliances.get(appliance)
            missing = expected - len(records) if expected is not None else 0
            category = category_label(records[0].category)
            out.append(
                f'<details class="g"{" open" if failed else ""}><summary><b>{esc(appliance)}'
                f'</b> <span class="muted">{esc(category)}</span> — '
                f"{_count(failed, len(records) - failed, missing)}</summary>"
            )
            for record in records:
                out.append(_task_line(record, index))
                index += 1
            out.append("</details>")
        out.append("</section>")
    out.append(
        f'<script type="text/plain" id="{DATA_ID}">{encode(viewer_data(ordered))}</script>'
    )  # a data block: text/plain is never executed, and base64 cannot close the element
    return out
