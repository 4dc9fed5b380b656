"""What the report says about reading: goals parsed from the instructions, read beliefs.

Per task, the goal the parser read from the instruction (in the belief's names) next to the
stored goal (in the truth's), and whether they are the same under the reader's alignment; per
appliance, how the read belief differs from the truth. One record per task is enough: every
method of a run parses against the same belief (the oracle, given the truth, is skipped).
"""

from __future__ import annotations

from typing import Any

from apbot.bench.records import TaskRecord
from apbot.bench.report.snapshot import RunData
from apbot.bench.report.text import value_text


def _goal_text(goal: dict[str, Any] | None) -> str:
    if goal is None:
        return "(none: the instruction could not be read)"
    return ", ".join(f"{k}={value_text(v)}" for k, v in goal.items()) or "(empty)"


def _per_task(data: RunData) -> list[TaskRecord]:
    """The first record of every task whose method read its goal (first learning step only)."""
    seen: dict[tuple[str, str], TaskRecord] = {}
    for record in data.records:
        if record.goal_mode != "read":
            continue
        seen.setdefault((record.appliance, record.task), record)
    return [seen[key] for key in sorted(seen)]


def read_goal_rows(data: RunData) -> tuple[str, list[str], list[list[tuple[str, bool]]]]:
    """A summary line, and the per-task table: stored goal, read goal, same or not."""
    records = _per_task(data)
    if not records:
        return "", [], []
    exact = sum(1 for r in records if r.goal_exact)
    line = (
        f"{exact} of {len(records)} tasks: the goal read from the instruction is the stored goal "
        "(compared under the reader's alignment of the belief with the truth)."
    )
    header = ["task", "stored goal (truth's names)", "read goal (belief's names)", "same"]
    rows = [
        [
            (f"{r.appliance}/{r.task}", False),
            (_goal_text(r.goal), False),
            (_goal_text(r.parsed_goal), False),
            ("✓" if r.goal_exact else "✗", not r.goal_exact),
        ]
        for r in records
    ]
    return line, header, rows


def belief_sections(data: RunData) -> list[tuple[str, str, list[str]]]:
    """(appliance, belief hash, differences from the truth) for every read belief."""
    found: dict[str, tuple[str, list[str]]] = {}
    for record in data.records:
        if record.belief == "read" and record.belief_hash and record.learnt_from == 0:
            found.setdefault(record.appliance, (record.belief_hash, list(record.belief_diff)))
    return [(a, h, d) for a, (h, d) in sorted(found.items())]
