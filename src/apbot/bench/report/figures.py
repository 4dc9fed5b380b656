"""The report's figures, drawn from a loaded run."""

from __future__ import annotations

from dataclasses import dataclass

from apbot.bench import plots
from apbot.bench.report.snapshot import RunData

FIGURES_DIR = "figures"


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
