"""Executing a run's pending work: in this process or a pool of worker processes, in small
batches (one chain per appliance when learning), yielding records as tasks finish, until done
or stopped.

Kept apart from :mod:`apbot.bench.runner` (what to run, the run directory, the summary)
because scheduling and stopping workers is its own concern with its own failure modes.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator
from concurrent.futures import FIRST_COMPLETED, Future, wait
from concurrent.futures.process import BrokenProcessPool

from apbot.bench.records import TaskRecord
from apbot.bench.stopping import WORKER_DIED, Stop
from apbot.bench.task_run import RunSettings, WorkItem, run_item
from apbot.bench.workers import worker_pool
from apbot.llm.limits import BudgetSpent

LLM_BUDGET = "LLM budget"


def _batches(items: list[WorkItem], workers: int) -> list[list[WorkItem]]:
    """Small enough to balance and to stop quickly; big enough that shipping is cheap."""
    size = max(1, min(16, len(items) // (workers * 8)))
    return [items[i : i + size] for i in range(0, len(items), size)]


Batch = tuple[list[WorkItem], frozenset[str] | None]
"""Items run in one go, and (learning) the task ids whose records are wanted (None: all)."""


def _work_batches(
    pending: list[WorkItem], work: list[WorkItem], settings: RunSettings, workers: int
) -> list[Batch]:
    """Small batches of pending items; when learning, one batch per (method, appliance) chain
    holding every selected task up to the last pending one (earlier tasks are run again, not
    recorded again: the belief a task starts from is the one the tasks before it left)."""
    if not settings.learn:
        return [(items, None) for items in _batches(pending, workers)]
    wanted: dict[tuple[str, str], set[str]] = {}
    for item in pending:
        wanted.setdefault((item.method, item.appliance), set()).add(item.task)
    batches: list[Batch] = []
    for (method, appliance), tasks in wanted.items():
        chain = [w for w in work if (w.method, w.appliance) == (method, appliance)]
        last = max(i for i, w in enumerate(chain) if w.task in tasks)
        batches.append((chain[: last + 1], frozenset(tasks)))
    return batches


def _run_batch(batch: Batch, settings: RunSettings) -> list[TaskRecord]:
    items, wanted = batch
    if settings.learn:
        from apbot.bench.learn import run_chain

        return list(run_chain(items, settings, wanted))
    return [run_item(item, settings)[0] for item in items]


def _execute(
    batches: list[Batch], settings: RunSettings, workers: int, stop: Stop
) -> Iterator[TaskRecord]:
    """Yield records as tasks finish, in this process or a pool, until done or stopped.

    Once a stop is requested, batches no worker has started are cancelled and the running
    ones finish; a second signal abandons those too. A worker that dies (killed, out of
    memory) stops the run the same way, keeping what finished.
    """
    if workers == 1 or sum(len(items) for items, _ in batches) <= 1:
        try:
            for items, wanted in batches:
                if settings.learn:
                    from apbot.bench.learn import run_chain

                    for record in run_chain(items, settings, wanted):
                        yield record
                        if stop.requested:
                            return
                    continue
                for item in items:
                    if stop.requested:
                        return
                    yield run_item(item, settings)[0]
        except KeyboardInterrupt:
            stop.request("SIGINT")
        except BudgetSpent as exc:
            stop.request(f"{LLM_BUDGET}: {exc}")
        return
    queue = deque(batches)
    window = workers * 2
    pool = worker_pool(min(workers, len(queue)))
    running: set[Future[list[TaskRecord]]] = set()
    try:
        while queue or running:
            while queue and len(running) < window and not stop.requested:
                running.add(pool.submit(_run_batch, queue.popleft(), settings))
            if stop.requested:
                running = {future for future in running if not future.cancel()}
            if not running or stop.hard:
                break
            finished, _ = wait(running, timeout=0.25, return_when=FIRST_COMPLETED)
            for future in finished:
                running.discard(future)
                try:
                    records = future.result()
                except BrokenProcessPool:  # the others fail alike, soon: keep what finished
                    stop.request(WORKER_DIED)
                    continue
                except BudgetSpent as exc:  # the batch's finished tasks run again next time
                    stop.request(f"{LLM_BUDGET}: {exc}")
                    continue
                yield from records
    finally:
        if running:  # abandoned after a second signal (or an error): end the workers now
            for process in list(getattr(pool, "_processes", {}).values()):
                process.kill()
        pool.shutdown(wait=True, cancel_futures=True)
