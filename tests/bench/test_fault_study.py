"""The fault study: one resumable run per (rate, seed), figures averaged over seeds, a plot."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from apbot.bench.fault_study import (
    PLOT_FILE,
    STUDY_FILE,
    average,
    run_directory,
    run_fault_study,
    study_figure,
    study_rows,
)


def _overall(sr: float, spl: float, n: int = 2) -> dict[str, object]:
    return {
        "methods": {
            "m": {
                "overall": {
                    "sr": sr,
                    "spl": spl,
                    "reasoning_steps": 2.0,
                    "execution_steps": 4.0,
                    "n": n,
                }
            }
        }
    }


def test_average_weighs_seeds_equally_and_marks_missing_runs() -> None:
    summaries = {
        (0.0, 0): _overall(1.0, 1.0),
        (0.0, 1): _overall(0.5, 0.25, n=4),
        (0.5, 0): {"methods": {}},
        (0.5, 1): {"methods": {}},
    }
    study = average(summaries, [0.0, 0.5], [0, 1], ["m"])
    assert study["rates"] == [0.0, 0.5] and study["seeds"] == [0, 1]
    assert study["methods"]["m"]["sr"] == [0.75, None]
    assert study["methods"]["m"]["spl"] == [0.625, None]
    assert study["methods"]["m"]["n"] == [6, 0]
    assert study_rows(study)[1][2:4] == ["–", "–"]


def test_study_runs_one_benchmark_per_rate_and_seed_and_resumes(tmp_path: Path) -> None:
    options = {
        "out": tmp_path,
        "workers": 1,
        "sample": 1,
        "progress": False,
        "appliances": ["kettle_1", "dehumidifier_3"],
    }
    study = run_fault_study([0.5, 0.0], ["oracle"], [0, 1], **options)
    assert study["rates"] == [0.0, 0.5]  # sorted
    assert study["methods"]["oracle"]["sr"] == [1.0, 1.0]  # the oracle ignores the belief
    assert study["methods"]["oracle"]["n"] == [4, 4]
    for rate in (0.0, 0.5):
        for seed in (0, 1):
            assert (run_directory(tmp_path, rate, seed) / "results.jsonl").exists()
    assert json.loads((tmp_path / STUDY_FILE).read_text()) == study
    assert (tmp_path / PLOT_FILE).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    results = run_directory(tmp_path, 0.5, 1) / "results.jsonl"
    before = results.read_text()
    assert run_fault_study([0.0, 0.5], ["oracle"], [0, 1], **options) == study
    assert results.read_text() == before  # resumed: nothing ran again


@pytest.mark.parametrize(
    ("rates", "methods", "message"),
    [
        ([0.1, 1.5], ["oracle"], "outside 0..1"),
        ([0.1, 0.1], ["oracle"], "given twice"),
        ([], ["oracle"], "at least one fault rate"),
        ([0.1], ["oracel"], "unknown method"),
    ],
)
def test_bad_study_options_are_refused_before_any_run(
    tmp_path: Path, rates: list[float], methods: list[str], message: str
) -> None:
    with pytest.raises(ValueError, match=message):
        run_fault_study(rates, methods, [0], out=tmp_path / "study", progress=False)
    assert not (tmp_path / "study").exists()


def test_figure_has_an_sr_and_an_spl_panel_with_a_line_per_method() -> None:
    study = {
        "rates": [0.0, 0.5],
        "seeds": [0],
        "methods": {
            "a": {"sr": [1.0, 0.5], "spl": [1.0, 0.4]},
            "b": {"sr": [1.0, None], "spl": [0.9, None]},
        },
    }
    axes = study_figure(study).axes
    assert [ax.get_title() for ax in axes] == ["Success rate", "SPL"]
    assert [len(ax.lines) for ax in axes] == [2, 2]
    assert list(axes[0].lines[1].get_xdata()) == [0.0]  # the missing point is left out
