"""The report as one self-contained HTML page."""

from __future__ import annotations

import base64
import hashlib
from collections.abc import Mapping, Sequence
from importlib import resources

from apbot.bench.report.content import (
    PARTIAL_NOTE,
    READING_GUIDE,
    REFERENCE_NOTE,
    SPL_TABLE,
    SR_TABLE,
    TABLE_NOTE,
    fault_rows,
    goal_rows,
    header_facts,
    progress,
    pvalue_rows,
    table,
)
from apbot.bench.report.figures import ReportFigure
from apbot.bench.report.snapshot import RunData
from apbot.bench.report.text import esc
from apbot.bench.report.traces import traces_html


def _asset(name: str) -> str:
    return (resources.files("apbot.bench.report") / name).read_text(encoding="utf-8")


CSS = _asset("page.css")
SCRIPT = _asset("viewer.js")


def content_policy(script: str) -> str:
    """Nothing from outside the page; no script but the viewer, allowed by its hash, so an
    injected one would not run even if escaping failed."""
    digest = base64.b64encode(hashlib.sha256(script.encode("utf-8")).digest()).decode("ascii")
    return (
        f"default-src 'none'; img-src data:; style-src 'unsafe-inline'; "
        f"script-src 'sha256-{digest}'; form-action 'none'; base-uri 'none'"
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
    return (
        f'<div class="wide"><table class="num"><thead><tr>{head}</tr></thead>'
        f"<tbody>{body}</tbody></table></div>"
    )


def _img(figure: ReportFigure | None) -> str:
    if figure is None:
        return ""
    data = base64.b64encode(figure.data).decode("ascii")
    return f'<p><img alt="{esc(figure.title)}" src="data:{figure.mime};base64,{data}"></p>'


def _partial_banner(data: RunData) -> str:
    state = progress(data)
    if state.state != "partial":
        return ""
    return f'<p class="partial"><b>Partial run: {esc(state.text)}.</b> {esc(PARTIAL_NOTE)}</p>'


def render_html(data: RunData, figures: Mapping[str, ReportFigure], generated: str) -> str:
    """The report as one self-contained HTML page."""

    def section(title: str, anchor: str, *body: str) -> list[str]:
        return [f'<h2 id="{anchor}">{esc(title)}</h2>', *body]

    facts = "".join(f"<dt>{esc(k)}</dt><dd>{esc(v)}</dd>" for k, v in header_facts(data, generated))
    note = TABLE_NOTE + (REFERENCE_NOTE if data.reference else "")
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f'<meta http-equiv="Content-Security-Policy" content="{content_policy(SCRIPT)}">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        "<title>apbot benchmark report</title>",
        f"<style>{CSS}</style></head><body>",
        "<h1>apbot benchmark report</h1>",
        _partial_banner(data),
        f'<dl class="h">{facts}</dl>',
        f"<p>{esc(READING_GUIDE)}</p>",
    ]
    out += section(
        "Success rate / average reasoning steps", "sr", _html_table(*table(data, SR_TABLE))
    )
    out += section(
        "SPL / average execution steps",
        "spl",
        _html_table(*table(data, SPL_TABLE)),
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
            _html_table(*pvalue_rows(data)),
        )
    if "goal_variables" in figures:
        out += section(
            "Success vs number of goal variables",
            "goal-variables",
            _img(figures["goal_variables"]),
            _html_table(*goal_rows(data)),
        )
    if data.fault_study is not None and "fault_study" in figures:
        out += section(
            "Fault study",
            "faults",
            "<p>SR / SPL when model faults are injected into the belief at each rate.</p>",
            _img(figures["fault_study"]),
            _html_table(*fault_rows(data.fault_study)),
        )
    out += traces_html(data)
    out.append(f"<script>{SCRIPT}</script>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"
