"""The report as Markdown: tables, figure links and the failures with their reasons."""

from __future__ import annotations

import html
import re
from collections.abc import Mapping, Sequence
from typing import Any

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
from apbot.bench.report.figures import FIGURES_DIR, ReportFigure
from apbot.bench.report.reading import belief_sections, read_goal_rows
from apbot.bench.report.snapshot import RunData
from apbot.bench.report.text import failure_reason

MARKDOWN_FAILURES = 50


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


def _md_reading(data: RunData) -> list[str]:
    """Goals read from the instructions, per task; read beliefs' differences, per appliance."""
    out: list[str] = []
    line, header, rows = read_goal_rows(data)
    if rows:
        out += ["## Goals read from the instructions", "", md_text(line), ""]
        out += [*_md_table(header, rows), ""]
    sections = belief_sections(data)
    if sections:
        out += [
            "## Read beliefs",
            "",
            "How the model read from each manual differs from the truth, under the reader's "
            "evaluation alignment (judged with the truth; no method sees this).",
            "",
        ]
        for appliance, digest, differences in sections:
            shown = "; ".join(differences) if differences else "no difference found"
            out.append(f"- **{md_text(appliance)}** ({md_text(digest)}): {md_text(shown)}")
        out.append("")
    return out


def render_markdown(data: RunData, figures: Mapping[str, ReportFigure], generated: str) -> str:
    """The report as Markdown; figures are linked from ``figures/``."""

    def image(key: str) -> list[str]:
        if key not in figures:
            return []
        return [f"![{figures[key].title}]({FIGURES_DIR}/{figures[key].name})", ""]

    out = ["# apbot benchmark report", ""]
    state = progress(data)
    if state.state == "partial":
        out += [f"> **Partial run: {md_text(state.text)}.** {PARTIAL_NOTE}", ""]
    out += [f"- **{name}:** {md_text(value)}" for name, value in header_facts(data, generated)]
    out += ["", md_text(READING_GUIDE), ""]
    out += ["## Success rate / average reasoning steps", ""]
    out += [*_md_table(*table(data, SR_TABLE)), ""]
    out += ["## SPL / average execution steps", ""]
    out += [*_md_table(*table(data, SPL_TABLE)), ""]
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
        out += image("pvalues") + _md_table(*pvalue_rows(data)) + [""]
    if "goal_variables" in figures:
        out += ["## Success vs number of goal variables", ""]
        out += image("goal_variables") + _md_table(*goal_rows(data)) + [""]
    if data.fault_study is not None and "fault_study" in figures:
        out += [
            "## Fault study",
            "",
            "SR / SPL when model faults are injected into the belief at each rate.",
            "",
        ]
        out += image("fault_study") + _md_table(*fault_rows(data.fault_study)) + [""]
    out += _md_reading(data)
    out += _md_failures(data)
    out += ["", "Every task's trace is in `report.html`.", ""]
    return "\n".join(out)
