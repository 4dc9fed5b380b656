"""The report as one self-contained HTML page."""

from __future__ import annotations

import base64
from collections.abc import Mapping, Sequence

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
.muted{color:#666}.partial{background:#fff3cd;border:1px solid #e0c36a;padding:.5em .8em}
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
        f'<meta http-equiv="Content-Security-Policy" content="{_CSP}">',
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
    out.append("</body></html>")
    return "\n".join(out) + "\n"
