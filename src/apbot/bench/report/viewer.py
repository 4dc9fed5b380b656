"""The trace viewer's data: every task's details and trace, each distinct trace stored once.

The page lists every task, but a task's instruction, goal table and trace are drawn by
``viewer.js`` only when it is opened, from one JSON document embedded in the page, gzipped
and base64-encoded. Nothing is cut: traces are kept whole, however long. Most traces are
identical across methods (the oracle and ApBot on the true model press the same buttons), so
the rows of each distinct trace are stored once and tasks refer to them by index; gzip takes
the rest of the repetition (the full benchmark's 4 MB of traces come to ~0.2 MB).

A row is built here, not in JavaScript, so that what it says is tested in Python: ``[class,
step, event, cell]`` (the cell spans the last two columns) or ``[class, step, event, cell,
cell]``. A cell is a string or a list of segments, each a string or ``[style, text]`` with
``style`` one of :data:`STYLES`. All text reaches the page through ``textContent``: it is never
parsed as HTML.
"""

from __future__ import annotations

import base64
import gzip
import json
from collections.abc import Mapping, Sequence
from typing import Any

from apbot.bench.records import TaskRecord
from apbot.bench.report.text import assignments, failure_reason, value_text

STYLES = ("mark", "ok", "bad", "muted", "rep")  # viewer.js draws exactly these
Segment = str | list[str]
Cell = str | list[Segment]
Row = list[Any]


def trace_rows(trace: Sequence[Mapping[str, Any]]) -> list[Row]:
    """A trace as table rows: one per event, except that consecutive exploration presses of
    the same action in the same step share a row, with every display in order."""
    runs: list[list[Mapping[str, Any]]] = []
    for event in trace:
        last = runs[-1][0] if runs else {}
        if (
            _exploring(event)
            and _exploring(last)
            and event.get("action") == last.get("action")
            and event.get("step") == last.get("step")
        ):
            runs[-1].append(event)
        else:
            runs.append([event])
    return [_event_row(run[0]) if len(run) == 1 else _explore_row(run) for run in runs]


def _exploring(event: Mapping[str, Any]) -> bool:
    return event.get("kind") == "action" and bool(event.get("exploring"))


def _event_row(event: Mapping[str, Any]) -> Row:
    kind = str(event.get("kind", ""))
    step = _step(event)
    text = str(event.get("text", ""))
    expected = _mapping(event.get("expected"))
    if kind == "macro":
        return ["m", step, "macro", text, f"expect {assignments(expected)}"]
    if kind == "action":
        shown: list[Segment] = [_shown(event) or ["muted", "(blank)"]]
        if event.get("accepted") is False:
            shown += [" ", ["bad", "refused"]]
        action = str(event.get("action", ""))
        if event.get("exploring"):
            return ["x", step, "explore", action, _cell(shown)]
        return ["", step, "", action, _cell(shown)]
    if kind == "check":
        verdict: Cell = [["ok" if text == "ok" else "bad", text]]
        return ["c", step, "check", verdict, _check_detail(expected, _mapping(event.get("values")))]
    if kind == "repair":
        verb = "repair failed" if text.startswith("could not") else "model repaired"
        return ["r", step, "repair", f"{verb}: {text}"]
    if kind == "explore":
        return ["x", step, "explored", text]
    if kind == "stop":
        return ["s", step, "stop", text]
    return ["", step, kind, text]


def _explore_row(events: Sequence[Mapping[str, Any]]) -> Row:
    """A run of exploration presses of one action: the displays in order, refusals counted."""
    shown: list[Segment] = [" → ".join(_shown(e) or "(blank)" for e in events)]
    refused = sum(e.get("accepted") is False for e in events)
    if refused:
        shown += [" ", ["bad", f"{refused} refused"]]
    first = events[0]
    action = f"{first.get('action', '')} ×{len(events)}"
    return ["x", _step(first), "explore", action, _cell(shown)]


def _check_detail(expected: Mapping[str, Any], observed: Mapping[str, Any]) -> Cell:
    """Expected vs observed per variable, mismatches marked."""
    parts: list[Segment] = []
    for name, want in expected.items():
        if name in observed and observed[name] != want:
            got = value_text(observed[name])
            parts.append(["mark", f"{name}: expected {value_text(want)}, observed {got}"])
        else:
            parts.append(f"{name}={value_text(want)}")
    parts += [
        ["mark", f"{name}: observed {value_text(v)}"]
        for name, v in observed.items()
        if name not in expected
    ]
    joined: list[Segment] = []
    for part in parts:
        if joined:
            joined.append("; ")
        joined.append(part)
    return _cell(joined)


def _cell(segments: list[Segment]) -> Cell:
    """Segments with neighbouring plain strings merged; a single plain string stays a string."""
    merged: list[Segment] = []
    for segment in segments:
        if isinstance(segment, str) and merged and isinstance(merged[-1], str):
            merged[-1] += segment
        else:
            merged.append(segment)
    if len(merged) == 1 and isinstance(merged[0], str):
        return merged[0]
    return merged


def _shown(event: Mapping[str, Any]) -> str:
    """What the appliance showed after an action: its display, else the values it reported."""
    display = event.get("display")
    if display not in (None, ""):
        return str(display)
    return assignments(_mapping(event.get("values")))


def _step(event: Mapping[str, Any]) -> int | str:
    step = event.get("step", "")
    return step if isinstance(step, int) and not isinstance(step, bool) else str(step)


def _mapping(value: Any) -> Mapping[str, Any]:
    """A trace field that should be a dict; anything else (a damaged record) shows as empty."""
    return value if isinstance(value, Mapping) else {}


def task_entry(record: TaskRecord, trace: int) -> dict[str, Any]:
    """What the viewer shows when a task is opened (and searches when the list is filtered)."""
    return {
        "m": record.method,
        "a": record.appliance,
        "t": record.task,
        "c": record.category,
        "ok": record.success,
        "why": failure_reason(record, limit=None),
        "ins": record.instruction,
        "goal": [
            [
                name,
                value_text(want),
                value_text(record.final_values[name]) if name in record.final_values else None,
            ]
            for name, want in record.goal.items()
        ],
        "claim": record.claimed_success,
        "gv": record.goal_variables,
        "faults": list(record.faults),
        "repairs": list(record.repairs),
        "tr": trace,
        "gm": record.goal_mode,
        "pg": (
            [[name, value_text(value)] for name, value in record.parsed_goal.items()]
            if record.parsed_goal is not None
            else None
        ),
        "gx": record.goal_exact,
        "go": list(record.goal_outside),
        "bh": record.belief_hash,
        "bd": list(record.belief_diff),
        "lf": record.learnt_from,
    }


def viewer_data(records: Sequence[TaskRecord]) -> dict[str, Any]:
    """The viewer's document: ``tasks`` in page order, ``traces`` each distinct one once."""
    index: dict[str, int] = {}
    traces: list[list[Row]] = []
    tasks = []
    for record in records:
        rows = trace_rows(record.trace)
        key = json.dumps(rows, ensure_ascii=False, separators=(",", ":"))
        if key not in index:
            index[key] = len(traces)
            traces.append(rows)
        tasks.append(task_entry(record, index[key]))
    return {"version": 1, "tasks": tasks, "traces": traces}


def encode(document: Mapping[str, Any]) -> str:
    """JSON, gzipped (no timestamp, so the same data gives the same bytes), in base64: only
    ``A-Za-z0-9+/=``, which nothing in an HTML page can misread."""
    raw = json.dumps(document, ensure_ascii=False, separators=(",", ":")).encode("utf-8")
    return base64.b64encode(gzip.compress(raw, compresslevel=9, mtime=0)).decode("ascii")


def decode(text: str) -> Any:
    """The inverse of :func:`encode` (what viewer.js does in the browser).

    >>> decode(encode({"tasks": [], "traces": [[["s", 1, "stop", "done"]]]}))["traces"][0]
    [['s', 1, 'stop', 'done']]
    """
    return json.loads(gzip.decompress(base64.b64decode(text)).decode("utf-8"))
