"""What a run set out to do, replayed from its ``run.json``, so a report can say how far it got.

``run.json`` keeps the bench's methods, belief, suite and selection (categories, appliances,
sample) and the number of (method, task) pairs selected. Replaying the selection with the
runner's own :func:`~apbot.bench.runner.select_work` on the suite gives the exact keys, so
records an earlier bench left in the same directory are told apart and every appliance knows
how many of its tasks are still to run. When the suite cannot be replayed (it moved, or
changed since: the replay selects another number of pairs), the count in ``run.json`` still
says how many tasks each method should have.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from apbot.bench.records import TaskRecord, record_key

if TYPE_CHECKING:
    from apbot.bench.runner import WorkItem

RUN_FILE = "run.json"


@dataclass(frozen=True)
class Selection:
    """The run's selected work, as far as it is known.

    ``tasks``: tasks per method (None: unknown). ``keys`` and ``appliances`` (tasks per
    appliance) are known only when the selection could be replayed; ``note`` says why not.
    """

    methods: tuple[str, ...] = ()
    belief: str | None = None
    tasks: int | None = None
    keys: frozenset[str] | None = None
    appliances: Mapping[str, int] = field(default_factory=dict)
    note: str = ""

    def includes(self, record: TaskRecord) -> bool:
        """Whether a record is part of this run (without keys: its method and belief are)."""
        if self.keys is not None:
            return record.key in self.keys
        if self.methods and record.method not in self.methods:
            return False
        return self.belief is None or record.belief == self.belief


def replay_selection(run: Mapping[str, Any]) -> Selection:
    """The selection recorded in ``run.json`` (parsed), replayed on its suite where possible."""
    listed = run.get("methods")
    if not (isinstance(listed, list) and listed and all(isinstance(m, str) for m in listed)):
        return Selection(note=f"{RUN_FILE} is missing or lists no methods")
    methods = tuple(dict.fromkeys(listed))
    belief = run["belief"] if isinstance(run.get("belief"), str) else None
    count = run.get("tasks")
    count = count if isinstance(count, int) and not isinstance(count, bool) else None
    work, note = _replay(run, methods) if belief is not None else (None, "")
    if work is not None and belief is not None and count in (None, len(work)):
        first = methods[0]
        return Selection(
            methods,
            belief,
            tasks=len(work) // len(methods),
            keys=frozenset(record_key(w.method, belief, w.appliance, w.task) for w in work),
            appliances=dict(Counter(w.appliance for w in work if w.method == first)),
        )
    if work is not None:
        note = (
            f"the suite now selects {len(work)} (method, task) pairs where {RUN_FILE} "
            f"says {count}: it changed since the run"
        )
    if count is not None and count % len(methods) == 0:
        return Selection(methods, belief, tasks=count // len(methods), note=note)
    return Selection(
        methods, belief, note=note or f"{RUN_FILE} does not say how many tasks were selected"
    )


def _replay(run: Mapping[str, Any], methods: tuple[str, ...]) -> tuple[list[WorkItem] | None, str]:
    """The runner's work list for the recorded selection, or why it cannot be had."""
    suite, chosen = run.get("suite"), run.get("selection")
    if not isinstance(suite, str) or not isinstance(chosen, dict):
        return None, f"{RUN_FILE} does not record the suite and selection"
    from apbot.bench.runner import BenchOptions, cached_suite, select_work

    options = BenchOptions(
        suite=suite,
        methods=list(methods),
        categories=chosen.get("categories"),
        appliances=chosen.get("appliances"),
        sample=chosen.get("sample"),
    )
    try:
        return select_work(options, cached_suite(suite)), ""
    except (ValueError, TypeError, KeyError, OSError) as exc:
        reason = next(iter(str(exc).splitlines()), "") or type(exc).__name__
        return None, f"the selection could not be replayed on suite {suite!r} ({reason})"
