"""The report's figures, drawn from a loaded run as SVG (text kept as text: small and sharp)."""

from __future__ import annotations

from dataclasses import dataclass

from apbot.bench import plots
from apbot.bench.report.snapshot import RunData

FIGURES_DIR = "figures"


@dataclass(frozen=True)
class ReportFigure:
    name: str
    title: str
    data: bytes
    mime: str = "image/svg+xml"


def make_figures(data: RunData) -> dict[str, ReportFigure]:
    """Every figure the run has data for, by section."""
    summary = data.summary
    methods = [m for m in data.methods if m in summary.methods]
    figures = {}
    if methods:
        overall = {m: summary.methods[m].overall.model_dump() for m in methods}
        figures["overview"] = ReportFigure(
            "overview.svg",
            "Overall performance",
            plots.svg_bytes(plots.overview_figure(methods, overall)),
        )
    if len(methods) > 1 and summary.pvalues:
        figures["pvalues"] = ReportFigure(
            "pvalues.svg",
            "χ² p-values between methods",
            plots.svg_bytes(plots.pvalue_figure(methods, summary.pvalues)),
        )
    with_counts = [m for m in methods if summary.goal_variables.get(m)]
    if with_counts:
        points = {
            m: {k: p.model_dump() for k, p in summary.goal_variables[m].items()}
            for m in with_counts
        }
        figures["goal_variables"] = ReportFigure(
            "goal_variables.svg",
            "Success rate vs number of goal variables",
            plots.svg_bytes(plots.goal_variables_figure(with_counts, points)),
        )
    if data.fault_study is not None and data.fault_study.methods:
        study = data.fault_study
        figures["fault_study"] = ReportFigure(
            "fault_study.svg",
            "SR and SPL vs fault rate",
            plots.svg_bytes(
                plots.fault_study_figure(
                    study.rates, {m: s.model_dump() for m, s in study.methods.items()}
                )
            ),
        )
    return figures
