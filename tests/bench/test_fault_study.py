"""The fault study: one resumable run per (rate, seed) or per kind, figures averaged over seeds,
a table per fault kind with the false success claims, a plot."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from apbot.bench.fault_study import (
    ANY,
    NONE,
    PLOT_FILE,
    STUDY_FILE,
    average,
    directory_table,
    kind_rows,
    per_kind,
    run_directory,
    run_fault_study,
    study_figure,
    study_rows,
)
from apbot.bench.records import TaskRecord


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
    assert study["mode"] == "mixed" and study["feedback"] == "display"
    assert study["methods"]["oracle"]["false_claims"] == [0, 0]
    assert study["per_kind"]["oracle"][NONE]["n"] == [4, 4]  # the oracle's belief is the truth
    assert json.loads((tmp_path / STUDY_FILE).read_text()) == study
    assert (tmp_path / PLOT_FILE).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    results = run_directory(tmp_path, 0.5, 1) / "results.jsonl"
    before = results.read_text()
    assert run_fault_study([0.0, 0.5], ["oracle"], [0, 1], **options) == study
    assert results.read_text() == before  # resumed: nothing ran again


@pytest.mark.parametrize(
    ("rates", "methods", "extra", "message"),
    [
        ([0.1, 1.5], ["oracle"], {}, "outside 0..1"),
        ([0.1, 0.1], ["oracle"], {}, "given twice"),
        ([], ["oracle"], {}, "at least one fault rate"),
        ([0.1], ["oracel"], {}, "unknown method"),
        ([0.1], ["oracle"], {"feedback": "image"}, "unknown feedback mode 'image'"),
        ([0.1], ["oracle"], {"kinds": ["gaurd"]}, "unknown fault kind.*gaurd"),
    ],
)
def test_bad_study_options_are_refused_before_any_run(
    tmp_path: Path, rates: list[float], methods: list[str], extra: dict, message: str
) -> None:
    with pytest.raises(ValueError, match=message):
        run_fault_study(rates, methods, [0], out=tmp_path / "study", progress=False, **extra)
    assert not (tmp_path / "study").exists()


def _record(method: str, faults: list[str], success: bool, claimed: bool, spl: float) -> TaskRecord:
    return TaskRecord(
        key=f"{method}|faulty:0.3|a/{len(faults)}{success}{claimed}",
        method=method,
        belief="faulty:0.3",
        appliance="a",
        category="c",
        task="t",
        instruction="",
        goal={},
        goal_variables=1,
        success=success,
        claimed_success=claimed,
        reasoning_steps=1,
        execution_steps=1,
        optimal_steps=1,
        spl=spl,
        faults=faults,
    )


def test_per_kind_counts_a_record_for_each_kind_in_its_belief_and_the_false_claims() -> None:
    records = {
        0.3: [
            _record(
                "m", ["guard power_off: is missing", "display temp: labelled 'T'"], True, True, 0.5
            ),
            _record("m", ["guard running: also allows press_up"], False, True, 0.0),  # false claim
            _record("m", ["display temp: labelled 'T'"], False, False, 0.0),
            _record("m", [], True, True, 1.0),
        ]
    }
    table = per_kind(records, [0.3], ["m"])["m"]
    assert list(table) == ["display", "guard", ANY, NONE]  # kinds in FAULT_KINDS order
    assert table["guard"] == {"sr": [0.5], "spl": [0.25], "n": [2], "false_claims": [1]}
    assert table["display"] == {"sr": [0.5], "spl": [0.25], "n": [2], "false_claims": [0]}
    assert table[ANY]["n"] == [3] and table[ANY]["false_claims"] == [1]
    assert table[NONE] == {"sr": [1.0], "spl": [1.0], "n": [1], "false_claims": [0]}
    assert kind_rows({"m": table}, [0.3])[1] == ["guard", "m", "0.3", "2", "0.500", "0.250", "1"]
    only = per_kind(records, [0.3], ["m"], only=["entry_format"])["m"]
    assert only["entry_format"] == {"sr": [None], "spl": [None], "n": [0], "false_claims": [0]}


def test_single_kind_study_runs_each_kind_alone_on_the_appliances_it_can_hit(
    tmp_path: Path,
) -> None:
    study = run_fault_study(
        [1.0],
        ["apbot-open-loop"],
        [0],
        out=tmp_path,
        workers=1,
        sample=1,
        progress=False,
        appliances=["induction_cooker_2", "kettle_1"],  # kettle_1: no guard, no keypad
        feedback="values",
        single_kind=True,
        kinds=["guard", "entry_format"],
    )
    assert study["mode"] == "single-kind" and study["feedback"] == "values"
    assert study["kinds"] == ["entry_format", "guard"]
    for kind in ("entry_format", "guard"):
        run = json.loads((run_directory(tmp_path, 1.0, 0, kind) / "run.json").read_text())
        assert run["belief"] == f"faulty:1:{kind}" and run["feedback"] == "values"
        assert run["selection"]["appliances"] == ["induction_cooker_2"]
        assert study["per_kind"]["apbot-open-loop"][kind]["n"] == [1]
    assert study["per_kind"]["apbot-open-loop"][NONE]["n"] == [0]
    assert study["methods"]["apbot-open-loop"]["n"] == [2]
    rates, table = directory_table(tmp_path)
    assert rates == [1.0] and table == study["per_kind"]


def test_directory_table_refuses_a_directory_without_results(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"holds no results\.jsonl"):
        directory_table(tmp_path)


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
