"""Loading a run directory for the report: its summary, records, run.json and fault study."""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any, TypeVar

from pydantic import BaseModel, ConfigDict, ValidationError, field_validator, model_validator

from apbot.bench.records import TaskRecord
from apbot.bench.results import RESULTS_FILE, ResultsError, read_records
from apbot.bench.suite import CATEGORIES, GOAL_VARIABLES

SUMMARY_FILE = "summary.json"


RUN_FILE = "run.json"


FAULT_FILE = "fault_study.json"


_M = TypeVar("_M", bound=BaseModel)


class ReportError(ValueError):
    """A run directory the report cannot be made from; the message says what and where."""


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
    """summary.json as the runner writes it (extra keys are allowed and ignored)."""

    belief: str = ""
    methods: dict[str, MethodSummary]
    pvalues: dict[str, dict[str, float]] = {}
    goal_variables: dict[str, dict[str, GoalPoint]] = {}

    @field_validator("goal_variables")
    @classmethod
    def _counts_are_integers(cls, value: dict[str, dict[str, GoalPoint]]) -> Any:
        for method, points in value.items():
            bad = [k for k in points if not k.isdigit()]
            if bad:
                raise ValueError(f"{method}: goal-variable counts must be integers, got {bad[0]!r}")
        return value


class FaultSeries(_Loose):
    sr: list[float]
    spl: list[float]


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


@dataclass
class RunData:
    """Everything a report shows, loaded and checked."""

    directory: Path
    summary: Summary
    records: list[TaskRecord]
    run: dict[str, Any]
    fault_study: FaultStudy | None
    methods: list[str]
    categories: list[str]
    run_date: str
    reference: set[str] = field(default_factory=set)  # methods given the ground truth

    def failures(self) -> list[TaskRecord]:
        return [r for r in self.records if not r.success]


def load_run(directory: Path) -> RunData:
    """Read and check a run directory (summary.json required; the rest optional)."""
    directory = Path(directory)
    if not directory.is_dir():
        raise ReportError(f"{directory}: no such run directory")
    summary_path = directory / SUMMARY_FILE
    if not summary_path.exists():
        raise ReportError(
            f"{summary_path}: not found; run `apbot bench --out {directory}` "
            "first (it writes summary.json)"
        )
    summary = _parse(summary_path, Summary)
    study_path = directory / FAULT_FILE
    fault_study = _parse(study_path, FaultStudy) if study_path.exists() else None
    run = _read_json(directory / RUN_FILE) if (directory / RUN_FILE).exists() else {}
    if not isinstance(run, dict):
        raise ReportError(f"{directory / RUN_FILE}: expected a JSON object")
    methods = _method_order(summary, run)
    try:
        records = read_records(directory)
    except ResultsError as exc:
        raise ReportError(str(exc)) from None
    methods += sorted({r.method for r in records} - set(methods))
    rank = {m: i for i, m in enumerate(methods)}
    records.sort(key=lambda r: (rank[r.method], r.appliance, r.task, r.key))
    return RunData(
        directory,
        summary,
        records,
        run,
        fault_study,
        methods,
        _category_order(summary),
        _run_date(directory, run),
        _reference_methods(methods),
    )


def _read_json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as exc:
        raise ReportError(f"{path}:{exc.lineno}:{exc.colno}: not valid JSON ({exc.msg})") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ReportError(f"{path}: cannot be read ({exc})") from None


def _parse(path: Path, kind: type[_M]) -> _M:
    data = _read_json(path)
    try:
        return kind.model_validate(data)
    except ValidationError as exc:
        error = exc.errors()[0]
        where = ".".join(str(part) for part in error["loc"]) or "top level"
        raise ReportError(
            f"{path}: {where}: {error['msg']}; rewrite it with `apbot bench` (or the fault study)"
        ) from None


def _method_order(summary: Summary, run: Mapping[str, Any]) -> list[str]:
    """The run's method order (run.json) where known, then the rest as summary.json lists them."""
    listed = run.get("methods")
    first = (
        [m for m in listed if isinstance(m, str) and m in summary.methods]
        if isinstance(listed, list)
        else []
    )
    return list(dict.fromkeys(first + list(summary.methods)))


def _category_order(summary: Summary) -> list[str]:
    """The suite's categories by the number of variables a task sets (the paper's order of
    complexity), unknown ones after, by name."""
    present = {c for m in summary.methods.values() for c in m.categories}
    known = sorted((c for c in CATEGORIES if c in present), key=GOAL_VARIABLES.__getitem__)
    return known + sorted(present - set(CATEGORIES))


def _run_date(directory: Path, run: Mapping[str, Any]) -> str:
    """When the run started (and last wrote), from run.json; else the results file's time."""
    started, updated = _when(run.get("started")), _when(run.get("updated"))
    if started:
        return started + (f" (last updated {updated})" if updated and updated != started else "")
    for name in (RESULTS_FILE, SUMMARY_FILE):
        if (directory / name).exists():
            return _when((directory / name).stat().st_mtime) or "unknown"
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
