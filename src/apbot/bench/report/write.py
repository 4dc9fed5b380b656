"""Writing a report's files next to the run's results."""

from __future__ import annotations

import os
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

from apbot.bench.report.figures import FIGURES_DIR, make_figures
from apbot.bench.report.markdown import render_markdown
from apbot.bench.report.page import render_html
from apbot.bench.report.snapshot import ReportError, RunData, load_run

Clock = Callable[[], datetime]


def _now() -> datetime:
    return datetime.now(UTC)


def _write(path: Path, content: str | bytes) -> Path:
    """Write via a temporary file so a reader never sees half a report."""
    temporary = path.with_name(path.name + ".tmp")
    if isinstance(content, str):
        temporary.write_text(content, encoding="utf-8")
    else:
        temporary.write_bytes(content)
    os.replace(temporary, path)
    return path


def write_files(data: RunData, clock: Clock = _now) -> list[Path]:
    """Write ``report.md``, ``report.html`` and the figures for a loaded run; return the paths.

    Raises :class:`ReportError` naming the file that cannot be written (a read-only run
    directory, a full disk).
    """
    generated = clock().strftime("%Y-%m-%d %H:%M UTC")
    figures = make_figures(data)
    figure_dir = data.directory / FIGURES_DIR
    target = figure_dir
    try:
        figure_dir.mkdir(exist_ok=True)
        written = []
        for figure in figures.values():
            target = figure_dir / figure.name
            written.append(_write(target, figure.data))
        target = data.directory / "report.md"
        markdown = _write(target, render_markdown(data, figures, generated))
        target = data.directory / "report.html"
        page = _write(target, render_html(data, figures, generated))
    except OSError as exc:
        raise ReportError(f"{target}: cannot be written ({exc.strerror or exc})") from None
    return [markdown, page, *written]


def write_report(directory: Path, clock: Clock = _now) -> list[Path]:
    """Read a run directory once and write its report; return the paths written.

    Raises :class:`ReportError` when the directory holds no run, a damaged file, or cannot
    be written to.
    """
    return write_files(load_run(Path(directory)), clock)
