"""The runner on read beliefs and read goals (the defaults), and with --learn."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from apbot.bench.reading import model_digest
from apbot.bench.results import RESULTS_FILE, read_records
from apbot.bench.runner import BenchError, BenchOptions, cached_suite, run_benchmark, run_one


def _options(tmp_path: Path, **changes: object) -> BenchOptions:
    base = BenchOptions(
        methods=["apbot"], appliances=["kettle_1"], sample=3, workers=1, out=tmp_path / "run"
    )
    for name, value in changes.items():
        setattr(base, name, value)
    return base


def test_the_defaults_read_the_belief_and_the_goal() -> None:
    assert (BenchOptions().belief, BenchOptions().goal, BenchOptions().learn) == (
        "read",
        "read",
        False,
    )


def test_records_keep_the_parsed_goal_the_belief_hash_and_its_differences(tmp_path: Path) -> None:
    outcome = run_benchmark(_options(tmp_path, appliances=["blender_1"]), progress=False)
    assert len(outcome.records) == 3
    for record in outcome.records:
        assert record.belief == "read" and record.goal_mode == "read"
        assert record.parsed_goal is not None and record.goal_exact is not None
        assert record.belief_hash.startswith("sha256:") and record.belief_diff
        assert record.goal  # the stored goal, which success is judged on
    assert len({r.belief_hash for r in outcome.records}) == 1  # read once per appliance
    run = json.loads((tmp_path / "run" / "run.json").read_text())
    assert (run["belief"], run["goal"], run["learn"]) == ("read", "read", False)


def test_a_goal_read_on_the_true_model_is_judged_exact_and_the_oracle_keeps_the_stored_goal() -> (
    None
):
    record = run_one("apbot", "true", 0, "kettle_1", "t01", "bundled", goal="read")
    assert record.goal_mode == "read" and record.goal_exact is True
    assert record.parsed_goal == {"temperature": 80, "heating": "on"}
    oracle = run_one("oracle", "read", 0, "kettle_1", "t01", "bundled", goal="read")
    assert oracle.success and oracle.goal_mode == "given" and oracle.parsed_goal is None
    truth = cached_suite("bundled").get("kettle_1").model
    assert oracle.belief_hash == model_digest(truth) and oracle.belief_diff == []


def test_an_unreadable_instruction_fails_the_task_with_the_parsers_words() -> None:
    from apbot.bench.runner import _find, run_task
    from apbot.bench.suite import Task

    appliance, task = _find("bundled", "kettle_1", "t01")
    odd = Task.model_construct(id="t01", instruction="x" * 6000, goal=task.goal, optimal_steps=None)
    record = run_task(appliance, odd, "apbot", "true", goal="read")
    assert not record.success and record.parsed_goal is None and record.execution_steps == 0
    assert "cannot read the instruction" in record.failure
    # a value the belief lacks is handed over as said: the agent looks for it, then says so
    hot = Task.model_construct(
        id="t01", instruction="Heat it to 120 degrees", goal=task.goal, optimal_steps=None
    )
    record = run_task(appliance, hot, "apbot", "true", goal="read")
    assert record.parsed_goal == {"temperature": 120, "heating": "on"} and record.goal_outside
    assert not record.success and "temperature=120 is not a value" in record.failure


def test_a_directory_does_not_mix_goal_modes_or_learning(tmp_path: Path) -> None:
    run_benchmark(_options(tmp_path, sample=1), progress=False)
    with pytest.raises(BenchError, match=r"goal 'read' \(asked: 'given'\)"):
        run_benchmark(_options(tmp_path, sample=1, goal="given"), progress=False)
    with pytest.raises(BenchError, match=r"learn False \(asked: True\)"):
        run_benchmark(_options(tmp_path, sample=1, learn=True), progress=False)


def test_learning_starts_each_task_from_the_belief_the_last_one_left(tmp_path: Path) -> None:
    options = _options(
        tmp_path, learn=True, belief="faulty:1", goal="given", appliances=["dehumidifier_1"]
    )
    outcome = run_benchmark(options, progress=False)
    by_task = {r.task: r for r in outcome.records}
    assert [by_task[t].learnt_from for t in ("t01", "t02", "t03")] == [0, 1, 2]
    assert by_task["t01"].repairs  # t01 repaired the faulty belief ...
    assert by_task["t02"].belief_hash != by_task["t01"].belief_hash  # ... and t02 starts there
    assert not by_task["t02"].repairs  # with nothing left to repair
    # a chain interrupted after its first task resumes with the same records
    lines = (tmp_path / "run" / RESULTS_FILE).read_text().splitlines()
    first = json.loads(lines[0])["task"]
    (tmp_path / "run" / RESULTS_FILE).write_text(lines[0] + "\n")
    resumed = run_benchmark(options, progress=False)
    assert resumed.ran == 2 and resumed.skipped == 1
    again = {r.task: r for r in read_records(tmp_path / "run")}
    for task, record in by_task.items():
        same = again[task].model_dump(exclude={"timings"})
        assert same == record.model_dump(exclude={"timings"}), (task, first)


def test_learning_in_worker_processes_gives_the_same_records(tmp_path: Path) -> None:
    chosen = {"learn": True, "belief": "faulty:1", "goal": "given"}
    alone = run_benchmark(_options(tmp_path, **chosen), progress=False).records
    pooled = run_benchmark(
        _options(
            tmp_path, **chosen, appliances=["kettle_1", "dehumidifier_1"], workers=2, rerun=True
        ),
        progress=False,
    ).records
    pooled = [r for r in pooled if r.appliance == "kettle_1"]
    assert [r.model_dump(exclude={"timings"}) for r in alone] == [
        r.model_dump(exclude={"timings"}) for r in pooled
    ]
