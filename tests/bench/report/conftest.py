"""The standard run's report, written once per test session (figures take most of the time)."""

from __future__ import annotations

from typing import Any

import pytest

from apbot.bench.report import write_report
from tests.bench.report.rundir import clock, write_run


@pytest.fixture(scope="session")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """The report of the standard run (:func:`~tests.bench.report.rundir.write_run`)."""
    directory = write_run(tmp_path_factory.mktemp("standard"))
    paths = write_report(directory, clock=clock)
    return {
        "dir": directory,
        "paths": paths,
        "md": (directory / "report.md").read_text(encoding="utf-8"),
        "html": (directory / "report.html").read_text(encoding="utf-8"),
    }
