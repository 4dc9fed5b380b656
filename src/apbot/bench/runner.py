"""Run methods over the suite: resumable, parallel, interruptible, judged on the true simulator.

Every finished (method, task) is appended to ``results.jsonl`` in the run directory at once,
so a run killed at any moment resumes where it stopped (finished keys are skipped) and ends
with the same records as an uninterrupted run. The directory itself (``run.json``, the lock)
is :mod:`apbot.bench.rundir`'s; stopping on a signal is :mod:`apbot.bench.stopping`'s.

Work runs in worker processes (``workers=1``: in this process) that die with the main process
(:mod:`apbot.bench.workers`), sent in small batches because one task often takes less time
than shipping it; only the main process writes files.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import apbot.vision.llm_policy  # noqa: F401  registers llm-policy-image (base deps only)
from apbot.agent.environment import FeedbackMode
from apbot.agent.registry import default_methods, methods
from apbot.bench.beliefs import BeliefError, parse_belief
from apbot.bench.execute import LLM_BUDGET as LLM_BUDGET
from apbot.bench.execute import Batch as Batch
from apbot.bench.execute import _execute, _work_batches
from apbot.bench.goals import parse_goal_mode
from apbot.bench.metrics import summarise
from apbot.bench.progress import progress as show_progress
from apbot.bench.provenance import code_version, suite_digest
from apbot.bench.records import TaskRecord, record_key
from apbot.bench.results import RESULTS_FILE, ResultStore, describe_recovery
from apbot.bench.rundir import BenchError, exclusive, prepare, run_directory, write_json
from apbot.bench.stopping import Stop, handling_signals
from apbot.bench.suite import Suite
from apbot.bench.task_run import RunSettings, WorkItem, cached_suite
from apbot.bench.task_run import _find as _find
from apbot.bench.task_run import image_environment as image_environment
from apbot.bench.task_run import run_item as run_item
from apbot.bench.task_run import run_one as run_one
from apbot.bench.task_run import run_task as run_task
from apbot.bench.task_run import run_task_learning as run_task_learning

SUMMARY_FILE = "summary.json"


def _default_methods() -> list[str]:
    return default_methods()


@dataclass
class BenchOptions:
    """What to run and where. ``sample``: only the first N tasks of each appliance."""

    suite: str = "bundled"
    methods: list[str] = field(default_factory=_default_methods)
    categories: list[str] | None = None
    appliances: list[str] | None = None
    sample: int | None = None
    workers: int = field(default_factory=lambda: os.cpu_count() or 1)
    out: Path | str = Path("runs/latest")
    belief: str = "read"
    seed: int = 0
    rerun: bool = False
    feedback: FeedbackMode = "display"
    goal: str = "read"  # "read": parsed from the instruction against the belief; "given"
    learn: bool = False  # each appliance's tasks in order, each from the belief the last left


@dataclass
class BenchOutcome:
    """The records of the selected work (finished so far), the summary written, and counts.

    ``interrupted``: the run stopped early (``stopped_by`` says why: "SIGINT", "SIGTERM" or a
    worker's death) and ``exit_code`` is what the command line exits with. ``notes``: what
    the run warned about (bad lines of the results file it quarantined).
    """

    records: list[TaskRecord]
    summary: dict[str, Any]
    out: Path
    interrupted: bool
    ran: int
    skipped: int
    stopped_by: str = ""
    exit_code: int = 0
    notes: list[str] = field(default_factory=list)  # warnings given during the run


# --- selecting the work -----------------------------------------------------------------------


def _unknown(what: str, bad: list[str], known: list[str]) -> BenchError:
    """An error naming the unknown names, the closest known one, and every valid name."""
    from apbot.model.values import closest_matches

    close = closest_matches(bad[0], known, limit=1)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    return BenchError(f"unknown {what} {', '.join(bad)}{hint}; known: {', '.join(known)}")


def select_work(options: BenchOptions, suite: Suite) -> list[WorkItem]:
    """The (method, task) pairs to run, interleaved so a partial run has some of everything.

    Order: the first task of every appliance (every method), then the second, and so on.
    Raises :class:`BenchError` for an unknown method, category or appliance, listing the
    valid ones.
    """
    known = list(methods())
    if not options.methods:
        raise BenchError(f"no methods selected; known: {', '.join(known)}")
    unknown = [m for m in options.methods if m not in known]
    if unknown:
        raise _unknown("method(s)", unknown, known)
    chosen = suite.appliances
    if options.categories:
        categories = sorted({a.category for a in suite.appliances})
        bad = [c for c in options.categories if c not in categories]
        if bad:
            raise _unknown("category(ies)", bad, categories)
        chosen = [a for a in chosen if a.category in options.categories]
    if options.appliances:
        ids = [a.id for a in suite.appliances]
        bad = [a for a in options.appliances if a not in ids]
        if bad:
            raise _unknown("appliance(s)", bad, ids)
        outside = [a for a in options.appliances if a not in {c.id for c in chosen}]
        if outside:
            raise BenchError(
                f"appliance(s) {', '.join(outside)} not in the selected "
                f"categories {', '.join(options.categories or [])}"
            )
        chosen = [a for a in chosen if a.id in options.appliances]
    if options.sample is not None and options.sample < 1:
        raise BenchError(f"--sample must be at least 1 (got {options.sample})")
    methods_in_order = list(dict.fromkeys(options.methods))
    depth = max((len(a.tasks) for a in chosen), default=0)
    if options.sample is not None:
        depth = min(depth, options.sample)
    return [
        WorkItem(m, a.id, a.tasks[i].id)
        for i in range(depth)
        for a in chosen
        if i < len(a.tasks)
        for m in methods_in_order
    ]


# --- the run ----------------------------------------------------------------------------------


def run_benchmark(options: BenchOptions, progress: bool = True) -> BenchOutcome:
    """Run the selected work into ``options.out``, skipping what is finished, and summarise.

    Returns with ``interrupted=True`` after Ctrl-C or SIGTERM (or when a worker process died),
    having kept every finished record. One run at a time per directory: a second one would
    cut the first one's half-written line.
    """
    return _run_benchmark(options, progress)


def _run_benchmark(options: BenchOptions, progress: bool) -> BenchOutcome:
    out = run_directory(options.out)
    spec = parse_belief(options.belief)
    if spec.kind == "faulty":
        try:
            import apbot.bench.faults  # noqa: F401
        except ImportError as exc:
            raise BeliefError(
                f"belief {str(spec)!r} needs fault injection, which is not available: {exc}"
            ) from None
    if options.workers < 1:
        raise BenchError(f"--workers must be at least 1 (got {options.workers})")
    goal_mode = parse_goal_mode(options.goal)
    try:
        suite = cached_suite(str(options.suite))
    except FileNotFoundError as exc:
        raise BenchError(str(exc)) from None
    work = select_work(options, suite)
    prepare(
        out,
        {
            "suite": str(options.suite),
            "belief": str(spec),
            "seed": options.seed,
            "feedback": options.feedback,
            "goal": goal_mode,
            "learn": options.learn,
        },
        {"code": code_version(), "suite_digest": suite_digest(suite)},
        {
            "methods": list(dict.fromkeys(options.methods)),
            "selection": {
                "categories": options.categories,
                "appliances": options.appliances,
                "sample": options.sample,
            },
            "tasks": len(work),
        },
        options.rerun,
        RESULTS_FILE,
    )
    with exclusive(out):
        store = ResultStore(out / RESULTS_FILE)
        if options.rerun:
            store.clear()
        recovered = store.recover()
        notes = [note] if (note := describe_recovery(store, recovered)) else []
        finished = recovered.records
        keys = {record_key(w.method, str(spec), w.appliance, w.task): w for w in work}
        pending = [w for k, w in keys.items() if k not in finished]
        done = [finished[k] for k in keys if k in finished]

        new: list[TaskRecord] = []
        stop = Stop(in_process=options.workers == 1 or len(pending) <= 1)
        per_method = {m: sum(w.method == m for w in work) for m in dict.fromkeys(options.methods)}
        with (
            show_progress(progress, options.methods, done, per_method) as advance,
            handling_signals(stop),
        ):
            stop.notice = advance.notice
            for note in notes:
                advance.notice(note)
            settings = RunSettings(
                str(spec),
                options.seed,
                str(options.suite),
                options.feedback,
                goal_mode,
                options.learn,
            )
            batches = _work_batches(pending, work, settings, options.workers)
            try:
                for record in _execute(batches, settings, options.workers, stop):
                    store.append(record)
                    new.append(record)
                    advance(record)
            except KeyboardInterrupt:  # a second signal between tasks, in this process
                stop.request("SIGINT")

        everything = store.load()
        selected = sorted((everything[k] for k in keys if k in everything), key=lambda r: r.key)
        summary = summarise(selected, belief=str(spec))
        write_json(out / SUMMARY_FILE, summary)
        return BenchOutcome(
            selected,
            summary,
            out,
            stop.requested,
            len(new),
            len(done),
            stopped_by=stop.reason,
            exit_code=stop.exit_code if stop.requested else 0,
            notes=notes,
        )
