"""``apbot report DIR``: a benchmark run as Markdown and as one self-contained HTML page.

The page is meant to be mailed or attached as a single file, so it carries everything inline:
CSS, figures as base64 PNGs, no scripts and no external references (a Content-Security-Policy
forbids them even if one slipped in). Model, instruction and trace text is untrusted input and
is escaped wherever it lands. Apart from the generation timestamp the output depends only on
the run directory, so two reports of the same run can be diffed.
"""

from __future__ import annotations

import base64
import html
import json
import os
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any, TypeVar

from pydantic import BaseModel, ConfigDict, ValidationError, field_validator, model_validator

from apbot.agent.episode import MAX_REASONING_STEPS
from apbot.bench import plots
from apbot.bench.records import TaskRecord
from apbot.bench.results import RESULTS_FILE, ResultsError, read_records
from apbot.bench.suite import CATEGORIES, GOAL_VARIABLES

SUMMARY_FILE = "summary.json"
RUN_FILE = "run.json"
FAULT_FILE = "fault_study.json"
FIGURES_DIR = "figures"
TRACE_ROWS = 200  # rows kept per failed task's trace (start and end; successes keep half)
MIN_TRACE_ROWS = 20
TRACE_ROW_BUDGET = 120_000  # rows in all traces together: about 10 MB of HTML
EXPLORE_SHOWN = 20  # displays listed at each end of a long exploration run
MARKDOWN_FAILURES = 50
REASON_CHARS = 160

_M = TypeVar("_M", bound=BaseModel)


class ReportError(ValueError):
    """A run directory the report cannot be made from; the message says what and where."""


# --- inputs ---------------------------------------------------------------------------------


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


# --- shared content -------------------------------------------------------------------------


READING_GUIDE = (
    "Every method gets the same tasks: an instruction and the target values of one or more "
    "settings (the goal). A task counts as a success only if the goal holds in the appliance's "
    "true final state — what the method believes or claims does not count — and the method "
    f"stayed within {MAX_REASONING_STEPS} reasoning steps. SR (success rate) is the share of "
    "tasks that succeeded. A reasoning step is one macro action the method decides on (such "
    "as 'set the timer'); presses made only to explore how a control behaves are not "
    "reasoning steps. An execution step is one physical action — a press, a turn, a hold — "
    "exploration included. Step counts are averaged over all tasks, failures included. SPL "
    "(success weighted by path length) credits each success with optimal ÷ max(optimal, "
    "taken) execution steps, the optimum being the oracle's plan on the true model, so a "
    "success that needed twice the presses counts half and a failure counts zero."
)

TABLE_NOTE = (
    "Categories are ordered by the number of variables a task sets. Best per column "
    "in bold (highest rate, then fewest steps)."
)
REFERENCE_NOTE = " † uses the ground-truth model: a reference, not ranked."

_SR_TABLE = ("sr", "reasoning_steps")
_SPL_TABLE = ("spl", "execution_steps")


def category_label(name: str) -> str:
    """``bottle_washer`` → ``Bottle washer``."""
    return name.replace("_", " ").capitalize()


def _cell_metrics(data: RunData, method: str, column: str) -> Metrics | None:
    entry = data.summary.methods.get(method)
    if entry is None:
        return None
    return entry.overall if column == "" else entry.categories.get(column)


def _best(data: RunData, column: str, keys: tuple[str, str]) -> set[str]:
    """The methods with the best cell in a column: highest rate, then fewest steps."""
    scored = {}
    for method in data.methods:
        metrics = _cell_metrics(data, method, column)
        if metrics is not None and method not in data.reference:
            scored[method] = (getattr(metrics, keys[0]), -getattr(metrics, keys[1]))
    if not scored:
        return set()
    top = max(scored.values())
    return {m for m, score in scored.items() if score == top}


def _table(data: RunData, keys: tuple[str, str]) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    """Header and rows of (cell text, bold) for one of the paper-style tables."""
    columns = [*data.categories, ""]
    header = ["Method", *(category_label(c) for c in data.categories), "Overall"]
    best = {c: _best(data, c, keys) for c in columns}
    rows = []
    for method in data.methods:
        label = method + (" †" if method in data.reference else "")
        row = [(label, False)]
        for column in columns:
            metrics = _cell_metrics(data, method, column)
            if metrics is None:
                row.append(("—", False))
            else:
                text = f"{getattr(metrics, keys[0]):.2f} / {getattr(metrics, keys[1]):.2f}"
                row.append((text, method in best[column]))
        rows.append(row)
    return header, rows


def _task_count(data: RunData) -> int:
    counts = [m.overall.n for m in data.summary.methods.values()]
    return max(counts, default=0)


def _belief(data: RunData) -> str:
    return data.summary.belief or str(data.run.get("belief", "")) or "unknown"


def failure_reason(record: TaskRecord) -> str:
    """Why a task failed, in one line."""
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
    return reason if len(reason) <= REASON_CHARS else reason[: REASON_CHARS - 1] + "…"


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


def _assignments(values: Mapping[str, Any]) -> str:
    return ", ".join(f"{k}={value_text(v)}" for k, v in values.items())


# --- figures ----------------------------------------------------------------------------------


@dataclass(frozen=True)
class ReportFigure:
    name: str
    title: str
    png: bytes


def make_figures(data: RunData) -> dict[str, ReportFigure]:
    """Every figure the run has data for, by section."""
    summary = data.summary
    methods = [m for m in data.methods if m in summary.methods]
    figures = {}
    if methods:
        overall = {m: summary.methods[m].overall.model_dump() for m in methods}
        figures["overview"] = ReportFigure(
            "overview.png",
            "Overall performance",
            plots.png_bytes(plots.overview_figure(methods, overall)),
        )
    if len(methods) > 1 and summary.pvalues:
        figures["pvalues"] = ReportFigure(
            "pvalues.png",
            "χ² p-values between methods",
            plots.png_bytes(plots.pvalue_figure(methods, summary.pvalues)),
        )
    with_counts = [m for m in methods if summary.goal_variables.get(m)]
    if with_counts:
        points = {
            m: {k: p.model_dump() for k, p in summary.goal_variables[m].items()}
            for m in with_counts
        }
        figures["goal_variables"] = ReportFigure(
            "goal_variables.png",
            "Success rate vs number of goal variables",
            plots.png_bytes(plots.goal_variables_figure(with_counts, points)),
        )
    if data.fault_study is not None and data.fault_study.methods:
        study = data.fault_study
        figures["fault_study"] = ReportFigure(
            "fault_study.png",
            "SR and SPL vs fault rate",
            plots.png_bytes(
                plots.fault_study_figure(
                    study.rates, {m: s.model_dump() for m, s in study.methods.items()}
                )
            ),
        )
    return figures


# --- Markdown -------------------------------------------------------------------------------


def md_text(text: Any) -> str:
    """Untrusted text made safe for a Markdown line or table cell (no HTML, no table breaks).

    >>> md_text("a|b <script>*x*</script>\\nnext")
    'a\\\\|b &lt;script&gt;\\\\*x\\\\*&lt;/script&gt; next'
    """
    text = " ".join(str(text).split())
    text = html.escape(text, quote=False)
    return re.sub(r"([\\`*_\[\]|#])", r"\\\1", text)


def _md_table(header: Sequence[str], rows: Sequence[Sequence[tuple[str, bool]]]) -> list[str]:
    lines = [
        "| " + " | ".join(md_text(h) for h in header) + " |",
        "|" + "|".join(["---"] + [":---:"] * (len(header) - 1)) + "|",
    ]
    for row in rows:
        cells = [f"**{md_text(t)}**" if bold else md_text(t) for t, bold in row]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def _pvalue_rows(data: RunData) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    methods = [m for m in data.methods if m in data.summary.methods]
    rows = []
    for a in methods:
        row = [(a, False)]
        for b in methods:
            p = data.summary.pvalues.get(a, {}).get(b, data.summary.pvalues.get(b, {}).get(a))
            if a == b or p is None:
                row.append(("—", False))
            else:
                significant = p < plots.SIGNIFICANT
                row.append((plots.format_p(p) + ("*" if significant else ""), significant))
        rows.append(row)
    return ["", *methods], rows


def _goal_rows(data: RunData) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    gv = data.summary.goal_variables
    methods = [m for m in data.methods if gv.get(m)]
    counts = sorted({int(k) for m in methods for k in gv[m]})
    rows = []
    for method in methods:
        row = [(method, False)]
        for count in counts:
            point = gv[method].get(str(count))
            row.append((f"{point.sr:.2f} (n={point.n})" if point else "—", False))
        rows.append(row)
    return ["Method", *(f"{c} variable{'s' if c != 1 else ''}" for c in counts)], rows


def _fault_rows(study: FaultStudy) -> tuple[list[str], list[list[tuple[str, bool]]]]:
    rows = []
    for method, series in study.methods.items():
        row = [(method, False)]
        row += [
            (f"{sr:.2f} / {spl:.2f}", False) for sr, spl in zip(series.sr, series.spl, strict=True)
        ]
        rows.append(row)
    return ["Method", *(f"rate {r:g}" for r in study.rates)], rows


def _header_facts(data: RunData, generated: str) -> list[tuple[str, str]]:
    facts = [("Suite", str(data.run.get("suite", "unknown"))), ("Belief", _belief(data))]
    if "seed" in data.run:
        facts.append(("Seed", str(data.run["seed"])))
    facts += [
        ("Methods", ", ".join(data.methods) or "none"),
        ("Tasks per method", str(_task_count(data))),
        ("Records", str(len(data.records))),
        ("Run", data.run_date),
        ("Report generated", generated),
    ]
    return facts


def _md_failures(data: RunData) -> list[str]:
    """Up to :data:`MARKDOWN_FAILURES` failures with their reasons, shared out between the
    methods so one weak method does not hide the others."""
    failures = data.failures()
    by_method = {m: [r for r in failures if r.method == m] for m in data.methods}
    by_method = {m: rs for m, rs in by_method.items() if rs}
    share = MARKDOWN_FAILURES // max(len(by_method), 1)
    shown = sum(min(len(rs), share) for rs in by_method.values())
    out = [f"## Failures ({shown} of {len(failures)})", ""]
    if not failures:
        out.append("None.")
    for method, records in by_method.items():
        out += [f"### {md_text(method)}: {len(records)} failed", ""]
        out += [
            f"- {md_text(r.appliance)}/{md_text(r.task)}: {md_text(failure_reason(r))}"
            for r in records[:share]
        ]
        if len(records) > share:
            out.append(f"- … and {len(records) - share} more")
        out.append("")
    return out


def render_markdown(data: RunData, figures: Mapping[str, ReportFigure], generated: str) -> str:
    """The report as Markdown; figures are linked from ``figures/``."""

    def image(key: str) -> list[str]:
        if key not in figures:
            return []
        return [f"![{figures[key].title}]({FIGURES_DIR}/{figures[key].name})", ""]

    out = ["# apbot benchmark report", ""]
    out += [f"- **{name}:** {md_text(value)}" for name, value in _header_facts(data, generated)]
    out += ["", md_text(READING_GUIDE), ""]
    out += ["## Success rate / average reasoning steps", ""]
    out += [*_md_table(*_table(data, _SR_TABLE)), ""]
    out += ["## SPL / average execution steps", ""]
    out += [*_md_table(*_table(data, _SPL_TABLE)), ""]
    out += [TABLE_NOTE + (REFERENCE_NOTE if data.reference else ""), ""]
    out += image("overview")
    if "pvalues" in figures:
        out += [
            "## Pairwise χ² tests",
            "",
            "p-values of the χ² test on success/failure "
            "counts for each pair of methods; * and bold: p < 0.05.",
            "",
        ]
        out += image("pvalues") + _md_table(*_pvalue_rows(data)) + [""]
    if "goal_variables" in figures:
        out += ["## Success vs number of goal variables", ""]
        out += image("goal_variables") + _md_table(*_goal_rows(data)) + [""]
    if data.fault_study is not None and "fault_study" in figures:
        out += [
            "## Fault study",
            "",
            "SR / SPL when model faults are injected into the belief at each rate.",
            "",
        ]
        out += image("fault_study") + _md_table(*_fault_rows(data.fault_study)) + [""]
    out += _md_failures(data)
    out += ["", "Every task's trace is in `report.html`.", ""]
    return "\n".join(out)


# --- HTML -----------------------------------------------------------------------------------


def esc(value: Any) -> str:
    """Anything as HTML text (quotes too, so it is safe in attributes)."""
    return html.escape(str(value), quote=True)


CSS = """
body{font:14px/1.45 system-ui,sans-serif;margin:2em auto;max-width:76em;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:.6em 0}th,td{border:1px solid #ccc;padding:2px 7px}
th{background:#f2f2f2}td.b{font-weight:bold}table.num td{text-align:center}
img{max-width:100%}dl.h{display:grid;grid-template-columns:max-content auto;gap:0 1em}
dl.h dt{font-weight:bold}details{margin:.15em 0}details.g>summary{font-weight:bold}
details.t{border-left:3px solid #ccc;padding-left:.5em}details.t.f{border-color:#c33}
details.t.s{border-color:#3a3}.ok{color:#080}.bad{color:#b00}.rep{background:#ffe38a}
table.tr{font:12px/1.3 ui-monospace,monospace}table.tr td{border-color:#e3e3e3}
tr.m td{background:#eef3fb}tr.x td{color:#666;font-style:italic}tr.r td{background:#ffe38a}
tr.c td{background:#f7f7f7}tr.s td{font-weight:bold}mark{background:#f99}
.muted{color:#666}
"""

_CSP = (
    "default-src 'none'; img-src data:; style-src 'unsafe-inline'; "
    "form-action 'none'; base-uri 'none'"
)


def _html_table(header: Sequence[str], rows: Sequence[Sequence[tuple[str, bool]]]) -> str:
    head = "".join(f"<th>{esc(h)}</th>" for h in header)
    body = "".join(
        "<tr>"
        + "".join(
            f'<td class="b">{esc(t)}</td>' if bold else f"<td>{esc(t)}</td>" for t, bold in row
        )
        + "</tr>"
        for row in rows
    )
    return f'<table class="num"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'


def _img(figure: ReportFigure | None) -> str:
    if figure is None:
        return ""
    data = base64.b64encode(figure.png).decode("ascii")
    return f'<p><img alt="{esc(figure.title)}" src="data:image/png;base64,{data}"></p>'


def _event_row(event: Mapping[str, Any]) -> str:
    """One trace event as a compact table row (end tags omitted: valid HTML, smaller)."""
    kind = str(event.get("kind", ""))
    step = esc(event.get("step", ""))
    text = esc(event.get("text", ""))
    expected, values = _mapping(event.get("expected")), _mapping(event.get("values"))
    if kind == "macro":
        expect = esc(_assignments(expected))
        return f'<tr class="m"><td>{step}<td>macro<td>{text}<td>expect {expect}'
    if kind == "action":
        shown = esc(_shown(event)) or '<span class="muted">(blank)</span>'
        refused = ' <span class="bad">refused</span>' if event.get("accepted") is False else ""
        if event.get("exploring"):
            return (
                f'<tr class="x"><td>{step}<td>explore<td>{esc(event.get("action"))}'
                f"<td>{shown}{refused}"
            )
        return f"<tr><td>{step}<td><td>{esc(event.get('action'))}<td>{shown}{refused}"
    if kind == "check":
        return f'<tr class="c"><td>{step}<td>check<td>{_check_text(text, expected, values)}'
    if kind == "repair":
        verb = "repair failed" if text.startswith("could not") else "model repaired"
        return f'<tr class="r"><td>{step}<td>repair<td colspan="2">{verb}: {text}'
    if kind == "explore":
        return f'<tr class="x"><td>{step}<td>explored<td colspan="2">{text}'
    if kind == "stop":
        return f'<tr class="s"><td>{step}<td>stop<td colspan="2">{text}'
    return f'<tr><td>{step}<td>{esc(kind)}<td colspan="2">{text}'


def _check_text(verdict: str, expected: Mapping[str, Any], observed: Mapping[str, Any]) -> str:
    """The check's verdict, then expected vs observed per variable, mismatches marked."""
    parts = []
    for name, want in expected.items():
        if name in observed and observed[name] != want:
            parts.append(
                f"<mark>{esc(name)}: expected {esc(value_text(want))}, observed "
                f"{esc(value_text(observed[name]))}</mark>"
            )
        else:
            parts.append(f"{esc(name)}={esc(value_text(want))}")
    parts += [
        f"<mark>{esc(name)}: observed {esc(value_text(v))}</mark>"
        for name, v in observed.items()
        if name not in expected
    ]
    css = "ok" if verdict == "ok" else "bad"
    return f'<span class="{css}">{verdict}</span><td>{"; ".join(parts)}'


def _shown(event: Mapping[str, Any]) -> str:
    """What the appliance showed after an action: its display, else the values it reported."""
    display = event.get("display")
    if display not in (None, ""):
        return str(display)
    return _assignments(_mapping(event.get("values")))


def _mapping(value: Any) -> Mapping[str, Any]:
    """A trace field that should be a dict; anything else (a damaged record) shows as empty."""
    return value if isinstance(value, Mapping) else {}


def _explore_row(events: Sequence[Mapping[str, Any]]) -> str:
    """A run of exploration presses of one action as one row: the displays in order."""
    shown = [_shown(e) or "(blank)" for e in events]
    if len(shown) > 2 * EXPLORE_SHOWN:
        shown = [
            *shown[:EXPLORE_SHOWN],
            f"… {len(shown) - 2 * EXPLORE_SHOWN} more …",
            *shown[-EXPLORE_SHOWN:],
        ]
    refused = sum(e.get("accepted") is False for e in events)
    note = f' <span class="bad">{refused} refused</span>' if refused else ""
    first = events[0]
    return (
        f'<tr class="x"><td>{esc(first.get("step", ""))}<td>explore'
        f"<td>{esc(first.get('action'))} ×{len(events)}<td>{esc(' → '.join(shown))}{note}"
    )


Row = list[Mapping[str, Any]]  # the events shown in one row of a trace table


def _trace_rows(trace: Sequence[Mapping[str, Any]]) -> list[Row]:
    """A trace grouped into table rows: one event each, except that consecutive exploration
    presses of the same action share a row. Rendering waits until it is known which rows
    are kept."""
    rows: list[Row] = []
    for event in trace:
        exploring = event.get("kind") == "action" and bool(event.get("exploring"))
        last = rows[-1][0] if rows else {}
        if (
            exploring
            and last.get("kind") == "action"
            and last.get("exploring")
            and event.get("action") == last.get("action")
            and event.get("step") == last.get("step")
        ):
            rows[-1].append(event)
        else:
            rows.append([event])
    return rows


def _render_row(row: Row) -> str:
    return _event_row(row[0]) if len(row) == 1 else _explore_row(row)


def _row_limit(records: Sequence[TaskRecord], rows: Mapping[str, list[Row]]) -> int:
    """Rows kept per failed task (successes keep half): :data:`TRACE_ROWS`, or fewer when the
    traces together would pass :data:`TRACE_ROW_BUDGET` and make the page too big to open."""

    def total(limit: int) -> int:
        return sum(min(len(rows[r.key]), _limit_for(r, limit)) for r in records)

    limit = TRACE_ROWS
    while limit > MIN_TRACE_ROWS and total(limit) > TRACE_ROW_BUDGET:
        limit = max(MIN_TRACE_ROWS, limit * 4 // 5)
    return limit


def _limit_for(record: TaskRecord, limit: int) -> int:
    return limit if not record.success else max(limit // 2, 1)


def _trace_table(rows: list[Row], limit: int) -> str:
    """The trace as a compact table; past ``limit`` rows the middle is cut (the start shows
    how the run went, the end why it stopped)."""
    if not rows:
        return '<p class="muted">No trace recorded.</p>'
    if len(rows) > limit:
        head = limit * 3 // 4
        shown = [
            *map(_render_row, rows[:head]),
            f'<tr><td colspan="4" class="muted">… {len(rows) - limit} more rows not shown …',
            *map(_render_row, rows[len(rows) - (limit - head) :]),
        ]
    else:
        shown = [_render_row(row) for row in rows]
    return (
        '<table class="tr"><thead><tr><th>step<th>event<th>action / check'
        "<th>display / detail</thead><tbody>\n" + "\n".join(shown) + "\n</tbody></table>"
    )


def _task_html(record: TaskRecord, rows: list[Row], limit: int) -> str:
    ok = record.success
    reason = failure_reason(record)
    mark = '<span class="ok">✓</span>' if ok else '<span class="bad">✗</span>'
    repaired = ' <span class="rep">repaired</span>' if record.repairs else ""
    summary = (
        f"{mark} {esc(record.appliance)}/{esc(record.task)} · R {record.reasoning_steps}"
        f" · E {record.execution_steps} (optimal {record.optimal_steps})"
        f" · SPL {record.spl:.2f}{repaired}" + ("" if ok else f" — {esc(reason)}")
    )
    goal_rows = "".join(
        f"<tr><td>{esc(name)}<td>{esc(value_text(want))}"
        f"<td>{esc(value_text(record.final_values[name])) if name in record.final_values else '—'}"
        for name, want in record.goal.items()
    )
    outcome = "success" if ok else f"failure: {esc(reason)}"
    parts = [
        f"<p><b>Instruction:</b> {esc(record.instruction)}</p>",
        f"<table><thead><tr><th>variable<th>goal<th>final (true)</thead><tbody>{goal_rows}"
        "</tbody></table>",
        f"<p><b>Outcome:</b> {outcome} · claimed success: "
        f"{'yes' if record.claimed_success else 'no'} · category {esc(record.category)} · "
        f"{record.goal_variables} goal variables</p>",
    ]
    if record.faults:
        parts.append(
            "<p><b>Faults injected:</b> " + "; ".join(esc(f) for f in record.faults) + "</p>"
        )
    if record.repairs:
        parts.append(
            '<p><b>Repairs:</b> <span class="rep">'
            + '</span>; <span class="rep">'.join(esc(r) for r in record.repairs)
            + "</span></p>"
        )
    parts.append(_trace_table(rows, _limit_for(record, limit)))
    css = "s" if ok else "f"
    return f'<details class="t {css}"><summary>{summary}</summary>\n{"".join(parts)}</details>'


def _slug(name: str) -> str:
    return "m-" + re.sub(r"[^A-Za-z0-9_-]", "-", name)


def _traces_html(data: RunData) -> list[str]:
    out = [
        '<h2 id="traces">Traces</h2>',
        '<p class="muted">Per method: failures first, then '
        "successes. Open a task for its instruction, goal, final values and trace. Rows: "
        "macro actions (blue), presses with the display after them, exploration (grey "
        "italics), checks (mismatches marked red), repairs of the model (yellow).</p>",
    ]
    by_method: dict[str, list[TaskRecord]] = {m: [] for m in data.methods}
    for record in data.records:
        by_method[record.method].append(record)
    rows = {r.key: _trace_rows(r.trace) for r in data.records}
    limit = _row_limit(data.records, rows)
    if limit < TRACE_ROWS:
        out.append(
            f'<p class="muted">The traces are long: each is cut to {limit} rows '
            f"({max(limit // 2, 1)} for successes), its start and its end, to keep this "
            "page small; results.jsonl has them in full.</p>"
        )
    out.append(
        "<ul>"
        + "".join(
            f'<li><a href="#{_slug(m)}">{esc(m)}</a>: {sum(not r.success for r in rs)} failed, '
            f"{sum(r.success for r in rs)} succeeded</li>"
            for m, rs in by_method.items()
        )
        + "</ul>"
    )
    for method, records in by_method.items():
        failed = [r for r in records if not r.success]
        passed = [r for r in records if r.success]
        out.append(f'<section id="{_slug(method)}"><h3>{esc(method)}</h3>')
        if not records:
            out.append('<p class="muted">No records.</p>')
        for title, group, is_open in (("Failures", failed, True), ("Successes", passed, False)):
            if group:
                out.append(
                    f'<details class="g"{" open" if is_open else ""}><summary>{title} '
                    f"({len(group)})</summary>"
                )
                out += [_task_html(r, rows[r.key], limit) for r in group]
                out.append("</details>")
        out.append("</section>")
    return out


def render_html(data: RunData, figures: Mapping[str, ReportFigure], generated: str) -> str:
    """The report as one self-contained HTML page."""

    def section(title: str, anchor: str, *body: str) -> list[str]:
        return [f'<h2 id="{anchor}">{esc(title)}</h2>', *body]

    facts = "".join(
        f"<dt>{esc(k)}</dt><dd>{esc(v)}</dd>" for k, v in _header_facts(data, generated)
    )
    note = TABLE_NOTE + (REFERENCE_NOTE if data.reference else "")
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f'<meta http-equiv="Content-Security-Policy" content="{_CSP}">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        "<title>apbot benchmark report</title>",
        f"<style>{CSS}</style></head><body>",
        "<h1>apbot benchmark report</h1>",
        f'<dl class="h">{facts}</dl>',
        f"<p>{esc(READING_GUIDE)}</p>",
    ]
    out += section(
        "Success rate / average reasoning steps", "sr", _html_table(*_table(data, _SR_TABLE))
    )
    out += section(
        "SPL / average execution steps",
        "spl",
        _html_table(*_table(data, _SPL_TABLE)),
        f'<p class="muted">{esc(note)}</p>',
        _img(figures.get("overview")),
    )
    if "pvalues" in figures:
        out += section(
            "Pairwise χ² tests",
            "pvalues",
            "<p>p-values of the χ² test on success/failure counts for each pair of "
            "methods; * and bold: p &lt; 0.05.</p>",
            _img(figures["pvalues"]),
            _html_table(*_pvalue_rows(data)),
        )
    if "goal_variables" in figures:
        out += section(
            "Success vs number of goal variables",
            "goal-variables",
            _img(figures["goal_variables"]),
            _html_table(*_goal_rows(data)),
        )
    if data.fault_study is not None and "fault_study" in figures:
        out += section(
            "Fault study",
            "faults",
            "<p>SR / SPL when model faults are injected into the belief at each rate.</p>",
            _img(figures["fault_study"]),
            _html_table(*_fault_rows(data.fault_study)),
        )
    out += _traces_html(data)
    out.append("</body></html>")
    return "\n".join(out) + "\n"


# --- writing ----------------------------------------------------------------------------------


def _write(path: Path, content: str | bytes) -> Path:
    """Write via a temporary file so a reader never sees half a report."""
    temporary = path.with_name(path.name + ".tmp")
    if isinstance(content, str):
        temporary.write_text(content, encoding="utf-8")
    else:
        temporary.write_bytes(content)
    os.replace(temporary, path)
    return path


def write_report(
    directory: Path, clock: Callable[[], datetime] = lambda: datetime.now(UTC)
) -> list[Path]:
    """Write ``report.md``, ``report.html`` and ``figures/*.png`` for a run; return the paths.

    Raises :class:`ReportError` when the directory has no (or a malformed) summary.json.
    """
    data = load_run(Path(directory))
    generated = clock().strftime("%Y-%m-%d %H:%M UTC")
    figures = make_figures(data)
    figure_dir = data.directory / FIGURES_DIR
    figure_dir.mkdir(exist_ok=True)
    pngs = [_write(figure_dir / f.name, f.png) for f in figures.values()]
    markdown = _write(data.directory / "report.md", render_markdown(data, figures, generated))
    page = _write(data.directory / "report.html", render_html(data, figures, generated))
    return [markdown, page, *pngs]
