"""``apbot bench --learn``: an agent that remembers what it repaired.

A household robot does not forget an appliance between two requests. With ``--learn`` each
appliance's tasks run in their order, and task k+1 starts from the belief task k ended with —
its repairs kept — instead of from the manual's reading again, unless that belief is not
to be trusted (``apbot.bench.memory``: an episode that ended in a declared failure, a belief
that fits the request worse than the manual). The first task of every appliance starts from
the run's belief as usual; a method that keeps no belief (the oracle) runs each task as
without ``--learn``.

A chain is deterministic, so a run interrupted in the middle of one resumes by running the
chain again from its first task and recording only the tasks that were not yet recorded.
"""

from __future__ import annotations

from collections.abc import Iterator

from apbot.bench.memory import keeps_belief
from apbot.bench.records import TaskRecord
from apbot.bench.task_run import RunSettings, WorkItem, run_item
from apbot.model.schema import ApplianceModel


def run_chain(
    items: list[WorkItem], settings: RunSettings, wanted: frozenset[str] | None = None
) -> Iterator[TaskRecord]:
    """Run one (method, appliance) chain of tasks in order, each from the belief the one
    before left; yield the records of the ``wanted`` tasks (all when None)."""
    learnt: ApplianceModel | None = None
    seen = 0  # the tasks the belief carried to the next one saw
    for item in items:
        record, after = run_item(item, settings, learnt, seen)
        if wanted is None or item.task in wanted:
            yield record
        if keeps_belief(record.claimed_success, after):
            learnt, seen = after, record.learnt_from + 1
        else:  # unconfirmed: the next request starts from the manual's reading again
            learnt, seen = None, 0
