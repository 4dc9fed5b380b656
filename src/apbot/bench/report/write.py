"""Writing a report's files next to the run's results."""

from __future__ import annotations

import os
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

from apbot.bench.report.figures import FIGURES_DIR, make_figures
from apbot.bench.report.markdown import render_markdown
from apbot.bench.report.page import render_html
from apbot.bench.report.snapshot import load_run


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
