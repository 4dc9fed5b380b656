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
import time
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import apbot.vision.llm_policy  # noqa: F401  registers llm-policy-image (base deps only)
from apbot.agent.environment import FeedbackMode, SimulatorEnvironment
from apbot.agent.episode import MAX_REASONING_STEPS, Episode, TaskContext, TraceEvent
from apbot.agent.registry import default_methods, get_method, methods
from apbot.bench.beliefs import BeliefError, BeliefSpec, belief_model, parse_belief
from apbot.bench.goals import GoalMode, MethodGoal, method_goal, parse_goal_mode
from apbot.bench.memory import fits_worse
from apbot.bench.metrics import summarise
from apbot.bench.progress import progress as show_progress
from apbot.bench.provenance import code_version, suite_digest
from apbot.bench.reading import BeliefFacts, belief_differences, model_digest
from apbot.bench.records import TaskRecord, record_key, spl
from apbot.bench.results import RESULTS_FILE, ResultStore, describe_recovery
from apbot.bench.rundir import BenchError, exclusive, prepare, run_directory, write_json
from apbot.bench.stopping import WORKER_DIED, Stop, handling_signals
from apbot.bench.suite import Suite, SuiteAppliance, Task, load_suite
from apbot.bench.workers import worker_pool
from apbot.llm.limits import BudgetSpent
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel

SUMMARY_FILE = "summary.json"
LLM_BUDGET = "LLM budget"


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


@dataclass(frozen=True)
class WorkItem:
    method: str
    appliance: str
    task: str


@dataclass(frozen=True)
class RunSettings:
    """What every task of a run shares (pinned in ``run.json``)."""

    belief: str = "read"
    seed: int = 0
    suite: str = "bundled"
    feedback: FeedbackMode = "display"
    goal: GoalMode = "read"
    learn: bool = False


# --- one task (runs in the workers) -----------------------------------------------------------

_SUITES: dict[str, Suite] = {}


def cached_suite(name: str) -> Suite:
    """The suite, loaded once per process (forked workers inherit the main process's copy)."""
    if name not in _SUITES:
        _SUITES[name] = load_suite(name)
    return _SUITES[name]


def _find(suite: str, appliance_id: str, task_id: str) -> tuple[SuiteAppliance, Task]:
    appliance = cached_suite(suite).get(appliance_id)
    for task in appliance.tasks:
        if task.id == task_id:
            return appliance, task
    raise KeyError(f"appliance {appliance_id!r} has no task {task_id!r}")


@lru_cache(maxsize=256)
def _belief(
    suite: str, appliance_id: str, spec: BeliefSpec, seed: int
) -> tuple[ApplianceModel, tuple[str, ...]]:
    """The belief model for an appliance (models are frozen, so one copy serves every task)."""
    model, faults = belief_model(cached_suite(suite).get(appliance_id), spec, seed)
    return model, tuple(faults)


@lru_cache(maxsize=256)
def _about_belief(suite: str, appliance_id: str, spec: BeliefSpec, seed: int) -> BeliefFacts:
    """The belief's hash and, for a read one, its differences from the truth (for reports)."""
    model, _faults = _belief(suite, appliance_id, spec, seed)
    truth = cached_suite(suite).get(appliance_id).model
    differences = belief_differences(model, truth) if spec.kind == "read" else []
    return BeliefFacts(model_digest(model), tuple(differences))


def _optimal(appliance: SuiteAppliance, task: Task, goal: dict[str, Any]) -> int:
    """The task's stored optimum, or the planner's on the ground truth when it is missing."""
    if task.optimal_steps is not None:
        return task.optimal_steps
    from apbot.plan.plan import plan

    return len(plan(appliance.model, None, goal))


def _describe(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {exc}"


def run_one(
    method: str,
    belief: str,
    seed: int,
    appliance_id: str,
    task_id: str,
    suite: str,
    feedback: FeedbackMode = "display",
    goal: GoalMode = "given",
) -> TaskRecord:
    """Run one method on one task and judge the result on the true simulator.

    Success means the task's goal (normalised on the true model) holds in the environment's
    final state and the method stayed within the reasoning-step limit; what the method claims
    is recorded but not trusted. An exception in the method gives a failed record.
    """
    settings = RunSettings(belief, seed, suite, feedback, goal)
    return run_item(WorkItem(method, appliance_id, task_id), settings)[0]


def run_item(
    item: WorkItem, settings: RunSettings, learnt: ApplianceModel | None = None, index: int = 0
) -> tuple[TaskRecord, ApplianceModel | None]:
    """:func:`run_one` on a work item; with ``learnt``, the method starts from that belief
    (``index`` tasks before this one left it). Also returns the belief the method ended with."""
    appliance, task = _find(settings.suite, item.appliance, item.task)
    spec = parse_belief(settings.belief)
    return run_task_learning(
        appliance,
        task,
        item.method,
        settings.belief,
        settings.seed,
        belief_of=lambda s: _belief(settings.suite, appliance.id, s, settings.seed),
        feedback=settings.feedback,
        goal_mode=settings.goal,
        facts=lambda: _about_belief(settings.suite, appliance.id, spec, settings.seed),
        learnt=learnt,
        index=index,
    )


def run_task(
    appliance: SuiteAppliance,
    task: Task,
    method: str,
    belief: str = "true",
    seed: int = 0,
    observer: Callable[[TraceEvent], None] | None = None,
    belief_of: Callable[[BeliefSpec], tuple[ApplianceModel, Any]] | None = None,
    feedback: FeedbackMode = "display",
    goal: GoalMode = "given",
) -> TaskRecord:
    """:func:`run_one` on objects: also for a task that is not in a suite (``apbot run``).

    ``observer`` sees every trace event as it happens; ``belief_of`` builds (or fetches a
    cached) belief model for the parsed belief spec; ``goal`` says whether the method gets
    the task's goal or reads it from the instruction. Raises :class:`ValueError` before
    anything runs when the stored goal is not a reachable state of the true appliance.
    """
    return run_task_learning(
        appliance, task, method, belief, seed, observer, belief_of, feedback, goal
    )[0]


def run_task_learning(
    appliance: SuiteAppliance,
    task: Task,
    method: str,
    belief: str = "true",
    seed: int = 0,
    observer: Callable[[TraceEvent], None] | None = None,
    belief_of: Callable[[BeliefSpec], tuple[ApplianceModel, Any]] | None = None,
    feedback: FeedbackMode = "display",
    goal_mode: GoalMode = "given",
    facts: Callable[[], BeliefFacts] | None = None,
    learnt: ApplianceModel | None = None,
    index: int = 0,
) -> tuple[TaskRecord, ApplianceModel | None]:
    """:func:`run_task`, optionally from a learnt belief, returning the belief it ended with."""
    from apbot.model.goal import GoalError
    from apbot.plan.plan import Unreachable

    try:
        goal = parse_goal(appliance.model, task.goal)
        optimal = _optimal(appliance, task, goal)
    except (GoalError, Unreachable) as exc:
        raise ValueError(
            f"{appliance.id}/{task.id}: the goal is not reachable on the appliance: {exc}"
        ) from None
    started = time.perf_counter()
    spec = parse_belief(belief)
    chosen = get_method(method)
    env: Any = (
        image_environment(appliance, appliance.model.actions, seed)
        if feedback == "image"
        else SimulatorEnvironment(appliance.model, feedback)
    )
    episode, error = Episode(), ""
    faults: tuple[str, ...] | list[str] = ()
    context: TaskContext | None = None
    asked = MethodGoal(dict(task.goal))
    digest = ""
    about: BeliefFacts | None = None
    try:
        if chosen.uses_truth:
            model, faults = appliance.model, ()
        elif belief_of is not None:
            model, faults = belief_of(spec)
        else:
            model, faults = belief_model(appliance, str(spec), seed)
        if not chosen.uses_truth:  # the oracle plans on the truth, to the stored goal
            asked = _asked(goal_mode, model, appliance, task)
            if learnt is not None:  # the learnt belief, unless it fits the request worse
                learnt_asked = _asked(goal_mode, learnt, appliance, task)
                if fits_worse(learnt, learnt_asked, model, asked):
                    learnt = None
                else:
                    model, faults, asked = learnt, (), learnt_asked
        about = facts() if facts is not None and learnt is None and not chosen.uses_truth else None
        digest = about.digest if about is not None else model_digest(model)
    except BudgetSpent:
        raise
    except Exception as exc:
        error = f"error: building the belief: {_describe(exc)}"
    else:
        if feedback == "image" and list(model.actions) != list(appliance.model.actions):
            env = image_environment(appliance, model.actions, seed)  # ground the belief's names
        if asked.goal is None:
            episode = Episode(failure=asked.error)
        else:
            context = TaskContext(
                appliance.id,
                appliance.category,
                task.id,
                task.instruction,
                asked.goal,
                model,
                appliance.manual,
                tuple(env.actions),
                observer=observer,
            )
            try:
                result = chosen.run(context, env)
                if not isinstance(result, Episode):
                    raise TypeError(f"method returned {type(result).__name__}, not an Episode")
                episode = result
            except BudgetSpent:
                raise  # not the task's failure: the run stops here and this task runs again later
            except Exception as exc:
                error = f"error: {_describe(exc)}"
    limit = context.max_reasoning_steps if context is not None else MAX_REASONING_STEPS
    final = {name: env.simulator.value(name) for name in goal}
    reached = all(final[name] == value for name, value in goal.items())
    within = episode.reasoning_steps <= limit
    success = not error and reached and within
    failure = "" if success else error or _failure(episode, goal, final, reached, limit)
    record = TaskRecord(
        key=record_key(method, str(spec), appliance.id, task.id),
        method=method,
        belief=str(spec),
        feedback=feedback,
        appliance=appliance.id,
        category=appliance.category,
        task=task.id,
        instruction=task.instruction,
        goal=dict(task.goal),
        goal_variables=len(task.goal),
        success=success,
        claimed_success=episode.claimed_success,
        reasoning_steps=episode.reasoning_steps,
        execution_steps=env.steps,
        optimal_steps=optimal,
        spl=spl(success, optimal, env.steps),
        failure=failure,
        repairs=list(episode.repairs),
        faults=list(faults),
        final_values=final,
        trace=[event.to_dict() for event in episode.trace],
        timings={"seconds": round(time.perf_counter() - started, 6)},
        llm_usage={
            k: episode.llm_usage.get(k, 0) + asked.usage.get(k, 0)
            for k in {**episode.llm_usage, **asked.usage}
        },
        goal_mode=goal_mode if not chosen.uses_truth else "given",
        parsed_goal=asked.parsed,
        goal_exact=asked.exact,
        goal_outside=list(asked.outside),
        belief_hash=digest,
        belief_diff=list(about.differences) if about is not None else [],
        learnt_from=index if learnt is not None else 0,
    )
    return record, episode.belief


def _asked(
    mode: GoalMode, model: ApplianceModel, appliance: SuiteAppliance, task: Task
) -> MethodGoal:
    """The goal a method working from ``model`` gets for ``task``."""
    return method_goal(
        mode, model, task.instruction, appliance.manual, dict(task.goal), appliance.model
    )


def image_environment(appliance: SuiteAppliance, actions: Iterable[str], seed: int) -> Any:
    """Image mode: the appliance as a rendered panel, grounded once per appliance and process
    (``apbot.vision``; needs the ``vision`` extra)."""
    from apbot.vision.mode import image_environment as build

    return build(appliance, list(actions), seed)


def _failure(
    episode: Episode, goal: dict[str, Any], final: dict[str, Any], reached: bool, limit: int
) -> str:
    """One line saying why a run failed, the method's own reason first."""
    parts = []
    if episode.reasoning_steps > limit:
        parts.append(f"over the reasoning-step limit ({episode.reasoning_steps} > {limit})")
    if episode.failure:
        parts.append(episode.failure)
    if not reached:
        wrong = ", ".join(
            f"{name}={final[name]!r} (want {value!r})"
            for name, value in goal.items()
            if final[name] != value
        )
        claim = "claimed success but " if episode.claimed_success and not episode.failure else ""
        parts.append(f"{claim}goal not met: {wrong}")
    return "; ".join(parts)


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


def _batches(items: list[WorkItem], workers: int) -> list[list[WorkItem]]:
    """Small enough to balance and to stop quickly; big enough that shipping is cheap."""
    size = max(1, min(16, len(items) // (workers * 8)))
    return [items[i : i + size] for i in range(0, len(items), size)]


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
