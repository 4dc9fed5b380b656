"""Values and reasons as short, safe text: shared by the Markdown, the page and the viewer."""

from __future__ import annotations

import html
import json
from collections.abc import Mapping
from typing import Any

from apbot.agent.episode import MAX_REASONING_STEPS
from apbot.bench.records import TaskRecord

REASON_CHARS = 160


def category_label(name: str) -> str:
    """``bottle_washer`` → ``Bottle washer``."""
    return name.replace("_", " ").capitalize()


def failure_reason(record: TaskRecord, limit: int | None = REASON_CHARS) -> str:
    """Why a task failed, in one line (cut to ``limit`` characters; None: in full)."""
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
    if limit is None or len(reason) <= limit:
        return reason
    return reason[: limit - 1] + "…"


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
    """``{"power": "on", "t": 2.0}`` → ``power=on, t=2``."""
    return ", ".join(f"{k}={value_text(v)}" for k, v in values.items())


def esc(value: Any) -> str:
    """Anything as HTML text (quotes too, so it is safe in attributes)."""
    return html.escape(str(value), quote=True)
