"""One consistent snapshot of a run directory: everything a report shows is derived from it.

A bench may still be appending to ``results.jsonl`` while a report is written, so the records
are read once (up to the last complete line) and every figure is computed from those records
with :func:`apbot.bench.metrics.summarise`. ``summary.json``, written at another moment, is
left to scripts: mixing it with fresher records is how a report came to say "44 tasks per
method" beside 116 traces each. What the run set out to do comes from ``run.json`` (see
:mod:`.selection`), so a partial run can say how far it got.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ConfigDict, ValidationError, model_validator

from apbot.bench.metrics import summarise
from apbot.bench.records import TaskRecord
from apbot.bench.report.selection import Selection, replay_selection
from apbot.bench.results import RESULTS_FILE, ResultsError, read_records
from apbot.bench.suite import CATEGORIES, GOAL_VARIABLES

RUN_FILE = "run.json"
FAULT_FILE = "fault_study.json"


class ReportError(ValueError):
    """A run directory the report cannot be made from; the message says what and where."""


# --- typed views of the summary (computed here) and of fault_study.json (read) ---------------


class _Loose(BaseModel):
    model_config = ConfigDict(extra="ignore")


class Metrics(_Loose):
    sr: float
    spl: float
    reasoning_steps: float
    execution_steps: float
    n: int


class MethodSummary(_Loose):
    overall: Metrics
    categories: dict[str, Metrics] = {}


class GoalPoint(_Loose):
    sr: float
    n: int


class Summary(_Loose):
    """What :func:`~apbot.bench.metrics.summarise` returns, with attribute access."""

    belief: str = ""
    methods: dict[str, MethodSummary]
    pvalues: dict[str, dict[str, float]] = {}
    goal_variables: dict[str, dict[str, GoalPoint]] = {}


class FaultSeries(_Loose):
    sr: list[float | None]  # None: no run of the method finished at that rate
    spl: list[float | None]


class FaultStudy(_Loose):
    """fault_study.json: SR and SPL per rate for every method (other keys are ignored)."""

    rates: list[float]
    seeds: list[int] = []
    methods: dict[str, FaultSeries]

    @model_validator(mode="after")
    def _one_value_per_rate(self) -> FaultStudy:
        for method, series in self.methods.items():
            for key in ("sr", "spl"):
                values = getattr(series, key)
                if len(values) != len(self.rates):
                    raise ValueError(
                        f"methods.{method}.{key} has {len(values)} values for "
                        f"{len(self.rates)} rates"
                    )
        return self


# --- the snapshot -----------------------------------------------------------------------------


@dataclass
class RunData:
    """Everything a report shows, from one read of the run directory.

    ``records`` are the run's selected records (all of them when the selection is unknown),
    ``summary`` is computed from exactly those, and ``outside`` counts the records of
    ``results.jsonl`` left out because an earlier bench into the same directory selected
    other methods or tasks.
    """

    directory: Path
    summary: Summary
    records: list[TaskRecord]
    run: dict[str, Any]
    fault_study: FaultStudy | None
    methods: list[str]
    categories: list[str]
    run_date: str
    selection: Selection
    outside: int = 0
    reference: set[str] = field(default_factory=set)  # methods given the ground truth

    def failures(self) -> list[TaskRecord]:
        return [r for r in self.records if not r.success]

    def finished(self) -> dict[str, int]:
        """Records per method, every method of the run included (0 when none finished)."""
        counts = dict.fromkeys(self.methods, 0)
        for record in self.records:
            counts[record.method] += 1
        return counts


def load_run(directory: Path) -> RunData:
    """Read a run directory once and derive everything the report shows from that read."""
    directory = Path(directory)
    if not directory.is_dir():
        raise ReportError(f"{directory}: no such run directory")
    run_path = directory / RUN_FILE
    if not run_path.exists() and not (directory / RESULTS_FILE).exists():
        raise ReportError(
            f"{directory}: no benchmark run here (neither {RUN_FILE} nor {RESULTS_FILE}); "
            f"run `apbot bench --out {directory}` first"
        )
    run = _read_json(run_path) if run_path.exists() else {}
    if not isinstance(run, dict):
        raise ReportError(f"{run_path}: expected a JSON object")
    study_path = directory / FAULT_FILE
    fault_study = _parse(study_path, FaultStudy) if study_path.exists() else None
    try:
        everything = read_records(directory)  # the one read of the results
    except ResultsError as exc:
        raise ReportError(str(exc)) from None
    except OSError as exc:
        raise ReportError(f"{directory / RESULTS_FILE}: cannot be read ({exc.strerror})") from None
    selection = replay_selection(run)
    records = [r for r in everything if selection.includes(r)]
    belief = str(run["belief"]) if isinstance(run.get("belief"), str) else None
    summary = Summary.model_validate(summarise(records, belief=belief))
    methods = list(selection.methods)
    methods += sorted({r.method for r in records} - set(methods))
    rank = {m: i for i, m in enumerate(methods)}
    records.sort(key=lambda r: (rank[r.method], r.appliance, r.task, r.key))
    return RunData(
        directory=directory,
        summary=summary,
        records=records,
        run=run,
        fault_study=fault_study,
        methods=methods,
        categories=_category_order(records),
        run_date=_run_date(directory, run),
        selection=selection,
        outside=len(everything) - len(records),
        reference=_reference_methods(methods),
    )


def _read_json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as exc:
        raise ReportError(f"{path}:{exc.lineno}:{exc.colno}: not valid JSON ({exc.msg})") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ReportError(f"{path}: cannot be read ({exc})") from None


def _parse(path: Path, kind: type[FaultStudy]) -> FaultStudy:
    data = _read_json(path)
    try:
        return kind.model_validate(data)
    except ValidationError as exc:
        error = exc.errors()[0]
        where = ".".join(str(part) for part in error["loc"]) or "top level"
        raise ReportError(
            f"{path}: {where}: {error['msg']}; write it again with the fault study"
        ) from None


def _category_order(records: Iterable[TaskRecord]) -> list[str]:
    """The suite's categories by the number of variables a task sets (the paper's order of
    complexity), unknown ones after, by name."""
    present = {r.category for r in records}
    known = sorted((c for c in CATEGORIES if c in present), key=GOAL_VARIABLES.__getitem__)
    return known + sorted(present - set(CATEGORIES))


def _run_date(directory: Path, run: Mapping[str, Any]) -> str:
    """When the run started (and last wrote), from run.json; else the results file's time."""
    started, updated = _when(run.get("started")), _when(run.get("updated"))
    if started:
        return started + (f" (last updated {updated})" if updated and updated != started else "")
    if (directory / RESULTS_FILE).exists():
        return _when((directory / RESULTS_FILE).stat().st_mtime) or "unknown"
    return "unknown"


def _when(stamp: Any) -> str:
    """An ISO time or a POSIX timestamp as ``YYYY-MM-DD HH:MM UTC`` ('' if neither).

    >>> _when("2026-11-22T04:13:45+00:00"), _when(0.0), _when(None)
    ('2026-11-22 04:13 UTC', '1970-01-01 00:00 UTC', '')
    """
    try:
        if isinstance(stamp, str):
            moment = datetime.fromisoformat(stamp)
            moment = moment.astimezone(UTC) if moment.tzinfo else moment.replace(tzinfo=UTC)
        elif isinstance(stamp, int | float) and not isinstance(stamp, bool):
            moment = datetime.fromtimestamp(stamp, UTC)
        else:
            return ""
    except (ValueError, OverflowError, OSError):
        return str(stamp) if isinstance(stamp, str) else ""
    return moment.strftime("%Y-%m-%d %H:%M UTC")


def _reference_methods(names: Iterable[str]) -> set[str]:
    """Methods that are handed the true model: shown, but not ranked against the others."""
    from apbot.agent.registry import methods

    known = methods()
    return {n for n in names if n in known and known[n].uses_truth}
