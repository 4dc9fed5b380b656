"""The trace viewer: every task's trace as a compact table, failures first."""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import Any

from apbot.bench.records import TaskRecord
from apbot.bench.report.snapshot import RunData
from apbot.bench.report.text import assignments, esc, failure_reason, value_text

TRACE_ROWS = 200  # rows kept per failed task's trace (start and end; successes keep half)


MIN_TRACE_ROWS = 20


TRACE_ROW_BUDGET = 120_000  # rows in all traces together: about 10 MB of HTML


EXPLORE_SHOWN = 20  # displays listed at each end of a long exploration run


def _event_row(event: Mapping[str, Any]) -> str:
    """One trace event as a compact table row (end tags omitted: valid HTML, smaller)."""
    kind = str(event.get("kind", ""))
    step = esc(event.get("step", ""))
    text = esc(event.get("text", ""))
    expected, values = _mapping(event.get("expected")), _mapping(event.get("values"))
    if kind == "macro":
        expect = esc(assignments(expected))
        return f'<tr class="m"><td>{step}<td>macro<td>{text}<td>expect {expect}'
    if kind == "action":
        shown = esc(_shown(event)) or '<span class="muted">(blank)</span>'
        refused = ' <span class="bad">refused</span>' if event.get("accepted") is False else ""
        if event.get("exploring"):
            return (
                f'<tr class="x"><td>{step}<td>explore<td>{esc(event.get("action"))}'
                f"<td>{shown}{refused}"
            )
        return f"<tr><td>{step}<td><td>{esc(event.get('action'))}<td>{shown}{refused}"
    if kind == "check":
        return f'<tr class="c"><td>{step}<td>check<td>{_check_text(text, expected, values)}'
    if kind == "repair":
        verb = "repair failed" if text.startswith("could not") else "model repaired"
        return f'<tr class="r"><td>{step}<td>repair<td colspan="2">{verb}: {text}'
    if kind == "explore":
        return f'<tr class="x"><td>{step}<td>explored<td colspan="2">{text}'
    if kind == "stop":
        return f'<tr class="s"><td>{step}<td>stop<td colspan="2">{text}'
    return f'<tr><td>{step}<td>{esc(kind)}<td colspan="2">{text}'


def _check_text(verdict: str, expected: Mapping[str, Any], observed: Mapping[str, Any]) -> str:
    """The check's verdict, then expected vs observed per variable, mismatches marked."""
    parts = []
    for name, want in expected.items():
        if name in observed and observed[name] != want:
            parts.append(
                f"<mark>{esc(name)}: expected {esc(value_text(want))}, observed "
                f"{esc(value_text(observed[name]))}</mark>"
            )
        else:
            parts.append(f"{esc(name)}={esc(value_text(want))}")
    parts += [
        f"<mark>{esc(name)}: observed {esc(value_text(v))}</mark>"
        for name, v in observed.items()
        if name not in expected
    ]
    css = "ok" if verdict == "ok" else "bad"
    return f'<span class="{css}">{verdict}</span><td>{"; ".join(parts)}'


def _shown(event: Mapping[str, Any]) -> str:
    """What the appliance showed after an action: its display, else the values it reported."""
    display = event.get("display")
    if display not in (None, ""):
        return str(display)
    return assignments(_mapping(event.get("values")))


def _mapping(value: Any) -> Mapping[str, Any]:
    """A trace field that should be a dict; anything else (a damaged record) shows as empty."""
    return value if isinstance(value, Mapping) else {}


def _explore_row(events: Sequence[Mapping[str, Any]]) -> str:
    """A run of exploration presses of one action as one row: the displays in order."""
    shown = [_shown(e) or "(blank)" for e in events]
    if len(shown) > 2 * EXPLORE_SHOWN:
        shown = [
            *shown[:EXPLORE_SHOWN],
            f"… {len(shown) - 2 * EXPLORE_SHOWN} more …",
            *shown[-EXPLORE_SHOWN:],
        ]
    refused = sum(e.get("accepted") is False for e in events)
    note = f' <span class="bad">{refused} refused</span>' if refused else ""
    first = events[0]
    return (
        f'<tr class="x"><td>{esc(first.get("step", ""))}<td>explore'
        f"<td>{esc(first.get('action'))} ×{len(events)}<td>{esc(' → '.join(shown))}{note}"
    )


Row = list[Mapping[str, Any]]  # the events shown in one row of a trace table


def _trace_rows(trace: Sequence[Mapping[str, Any]]) -> list[Row]:
    """A trace grouped into table rows: one event each, except that consecutive exploration
    presses of the same action share a row. Rendering waits until it is known which rows
    are kept."""
    rows: list[Row] = []
    for event in trace:
        exploring = event.get("kind") == "action" and bool(event.get("exploring"))
        last = rows[-1][0] if rows else {}
        if (
            exploring
            and last.get("kind") == "action"
            and last.get("exploring")
            and event.get("action") == last.get("action")
            and event.get("step") == last.get("step")
        ):
            rows[-1].append(event)
        else:
            rows.append([event])
    return rows


def _render_row(row: Row) -> str:
    return _event_row(row[0]) if len(row) == 1 else _explore_row(row)


def _row_limit(records: Sequence[TaskRecord], rows: Mapping[str, list[Row]]) -> int:
    """Rows kept per failed task (successes keep half): :data:`TRACE_ROWS`, or fewer when the
    traces together would pass :data:`TRACE_ROW_BUDGET` and make the page too big to open."""

    def total(limit: int) -> int:
        return sum(min(len(rows[r.key]), _limit_for(r, limit)) for r in records)

    limit = TRACE_ROWS
    while limit > MIN_TRACE_ROWS and total(limit) > TRACE_ROW_BUDGET:
        limit = max(MIN_TRACE_ROWS, limit * 4 // 5)
    return limit


def _limit_for(record: TaskRecord, limit: int) -> int:
    return limit if not record.success else max(limit // 2, 1)


def _trace_table(rows: list[Row], limit: int) -> str:
    """The trace as a compact table; past ``limit`` rows the middle is cut (the start shows
    how the run went, the end why it stopped)."""
    if not rows:
        return '<p class="muted">No trace recorded.</p>'
    if len(rows) > limit:
        head = limit * 3 // 4
        shown = [
            *map(_render_row, rows[:head]),
            f'<tr><td colspan="4" class="muted">… {len(rows) - limit} more rows not shown …',
            *map(_render_row, rows[len(rows) - (limit - head) :]),
        ]
    else:
        shown = [_render_row(row) for row in rows]
    return (
        '<table class="tr"><thead><tr><th>step<th>event<th>action / check'
        "<th>display / detail</thead><tbody>\n" + "\n".join(shown) + "\n</tbody></table>"
    )


def _task_html(record: TaskRecord, rows: list[Row], limit: int) -> str:
    ok = record.success
    reason = failure_reason(record)
    mark = '<span class="ok">✓</span>' if ok else '<span class="bad">✗</span>'
    repaired = ' <span class="rep">repaired</span>' if record.repairs else ""
    summary = (
        f"{mark} {esc(record.appliance)}/{esc(record.task)} · R {record.reasoning_steps}"
        f" · E {record.execution_steps} (optimal {record.optimal_steps})"
        f" · SPL {record.spl:.2f}{repaired}" + ("" if ok else f" — {esc(reason)}")
    )
    goal_rows = "".join(
        f"<tr><td>{esc(name)}<td>{esc(value_text(want))}"
        f"<td>{esc(value_text(record.final_values[name])) if name in record.final_values else '—'}"
        for name, want in record.goal.items()
    )
    outcome = "success" if ok else f"failure: {esc(reason)}"
    parts = [
        f"<p><b>Instruction:</b> {esc(record.instruction)}</p>",
        f"<table><thead><tr><th>variable<th>goal<th>final (true)</thead><tbody>{goal_rows}"
        "</tbody></table>",
        f"<p><b>Outcome:</b> {outcome} · claimed success: "
        f"{'yes' if record.claimed_success else 'no'} · category {esc(record.category)} · "
        f"{record.goal_variables} goal variables</p>",
    ]
    if record.faults:
        parts.append(
            "<p><b>Faults injected:</b> " + "; ".join(esc(f) for f in record.faults) + "</p>"
        )
    if record.repairs:
        parts.append(
            '<p><b>Repairs:</b> <span class="rep">'
            + '</span>; <span class="rep">'.join(esc(r) for r in record.repairs)
            + "</span></p>"
        )
    parts.append(_trace_table(rows, _limit_for(record, limit)))
    css = "s" if ok else "f"
    return f'<details class="t {css}"><summary>{summary}</summary>\n{"".join(parts)}</details>'


def slug(name: str) -> str:
    return "m-" + re.sub(r"[^A-Za-z0-9_-]", "-", name)


def traces_html(data: RunData) -> list[str]:
    out = [
        '<h2 id="traces">Traces</h2>',
        '<p class="muted">Per method: failures first, then '
        "successes. Open a task for its instruction, goal, final values and trace. Rows: "
        "macro actions (blue), presses with the display after them, exploration (grey "
        "italics), checks (mismatches marked red), repairs of the model (yellow).</p>",
    ]
    by_method: dict[str, list[TaskRecord]] = {m: [] for m in data.methods}
    for record in data.records:
        by_method[record.method].append(record)
    rows = {r.key: _trace_rows(r.trace) for r in data.records}
    limit = _row_limit(data.records, rows)
    if limit < TRACE_ROWS:
        out.append(
            f'<p class="muted">The traces are long: each is cut to {limit} rows '
            f"({max(limit // 2, 1)} for successes), its start and its end, to keep this "
            "page small; results.jsonl has them in full.</p>"
        )
    out.append(
        "<ul>"
        + "".join(
            f'<li><a href="#{slug(m)}">{esc(m)}</a>: {sum(not r.success for r in rs)} failed, '
            f"{sum(r.success for r in rs)} succeeded</li>"
            for m, rs in by_method.items()
        )
        + "</ul>"
    )
    for method, records in by_method.items():
        failed = [r for r in records if not r.success]
        passed = [r for r in records if r.success]
        out.append(f'<section id="{slug(method)}"><h3>{esc(method)}</h3>')
        if not records:
            out.append('<p class="muted">No records.</p>')
        for title, group, is_open in (("Failures", failed, True), ("Successes", passed, False)):
            if group:
                out.append(
                    f'<details class="g"{" open" if is_open else ""}><summary>{title} '
                    f"({len(group)})</summary>"
                )
                out += [_task_html(r, rows[r.key], limit) for r in group]
                out.append("</details>")
        out.append("</section>")
    return out
