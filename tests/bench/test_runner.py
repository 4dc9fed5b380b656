"""The benchmark runner: judged on the true state, resumable, robust to bad methods."""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from typer.testing import CliRunner

from apbot.agent.environment import Environment
from apbot.agent.episode import Episode, TaskContext
from apbot.agent.methods import run_oracle
from apbot.agent.registry import Method, register, unregister
from apbot.bench.beliefs import BeliefError, belief_model, parse_belief
from apbot.bench.results import QUARANTINE_FILE, RESULTS_FILE, read_records
from apbot.bench.runner import BenchError, BenchOptions, cached_suite, run_benchmark, run_one
from apbot.bench.stopping import WORKER_DIED
from apbot.cli import app


def _liar(context: TaskContext, env: Environment) -> Episode:
    """Claims success without touching the appliance."""
    return Episode(claimed_success=True, reasoning_steps=1)


def _crash(context: TaskContext, env: Environment) -> Episode:
    env.step(env.actions[0])
    raise RuntimeError("boom")


def _overthink(context: TaskContext, env: Environment) -> Episode:
    """Reaches the goal, but only after too many reasoning steps, and misreports its presses."""
    episode = run_oracle(context, env)
    episode.reasoning_steps = context.max_reasoning_steps + 1
    episode.execution_steps = 0
    return episode


def _interrupt(context: TaskContext, env: Environment) -> Episode:
    """Ctrl-C arrives while this method runs."""
    os.kill(os.getpid(), signal.SIGINT)
    return run_oracle(context, env)


def _terminate(context: TaskContext, env: Environment) -> Episode:
    """A plain ``kill`` arrives while this method runs."""
    os.kill(os.getpid(), signal.SIGTERM)
    return run_oracle(context, env)


def _die(context: TaskContext, env: Environment) -> Episode:
    """The worker running this is killed (as by the OOM killer or a user's ``kill -9``)."""
    os.kill(os.getpid(), signal.SIGKILL)
    raise AssertionError("unreachable")


FAKES = {
    "test-liar": _liar,
    "test-crash": _crash,
    "test-overthink": _overthink,
    "test-interrupt": _interrupt,
    "test-terminate": _terminate,
    "test-die": _die,
}


@pytest.fixture(scope="module", autouse=True)
def fake_methods() -> Iterator[None]:
    """The fakes exist for this module only: a default ``--methods`` elsewhere runs none."""
    for name, run in FAKES.items():
        register(Method(name, run, "a method for the runner's tests"))
    yield
    for name in FAKES:
        unregister(name)


def options(tmp_path: Path, **changes: object) -> BenchOptions:
    base = BenchOptions(
        methods=["oracle"],
        appliances=["kettle_1", "dehumidifier_1"],
        sample=1,
        workers=1,
        out=tmp_path / "run",
    )
    for name, value in changes.items():
        setattr(base, name, value)
    return base


def test_oracle_run_writes_records_run_json_and_summary(tmp_path: Path) -> None:
    outcome = run_benchmark(options(tmp_path), progress=False)
    assert (outcome.ran, outcome.skipped, outcome.interrupted) == (2, 0, False)
    assert all(r.success and r.spl == 1.0 for r in outcome.records)
    record = outcome.records[0]
    assert record.execution_steps == record.optimal_steps
    assert record.trace and record.trace[-1]["kind"] == "stop"
    assert set(record.final_values) == set(record.goal)
    run = json.loads((tmp_path / "run" / "run.json").read_text())
    assert (run["suite"], run["belief"], run["seed"], run["methods"]) == (
        "bundled",
        "read",
        0,
        ["oracle"],
    )
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary == outcome.summary
    assert summary["methods"]["oracle"]["overall"]["n"] == 2
    assert "timings" not in json.dumps(summary)


def test_resume_skips_finished_records(tmp_path: Path) -> None:
    first = run_benchmark(options(tmp_path), progress=False)
    again = run_benchmark(options(tmp_path), progress=False)
    assert (again.ran, again.skipped) == (0, 2)
    assert [r.key for r in again.records] == [r.key for r in first.records]
    wider = run_benchmark(options(tmp_path, sample=2), progress=False)
    assert (wider.ran, wider.skipped) == (2, 2)
    lines = (tmp_path / "run" / RESULTS_FILE).read_text().splitlines()
    assert len(lines) == 4 == len({json.loads(line)["key"] for line in lines})
    assert wider.summary["methods"]["oracle"]["overall"]["n"] == 4
    rerun = run_benchmark(options(tmp_path, rerun=True), progress=False)
    assert (rerun.ran, rerun.skipped) == (2, 0)
    assert len(read_records(tmp_path / "run")) == 2


def test_a_torn_last_line_is_dropped_and_rerun(tmp_path: Path) -> None:
    run_benchmark(options(tmp_path), progress=False)
    results = tmp_path / "run" / RESULTS_FILE
    lines = results.read_bytes().splitlines(keepends=True)
    results.write_bytes(lines[0] + lines[1][: len(lines[1]) // 2])  # killed mid-write
    outcome = run_benchmark(options(tmp_path), progress=False)
    assert (outcome.ran, outcome.skipped) == (1, 1)
    assert len(results.read_text().splitlines()) == 2
    assert all(r.success for r in read_records(tmp_path / "run"))


def test_a_bad_line_in_the_middle_is_quarantined_and_its_task_runs_again(tmp_path: Path) -> None:
    run_benchmark(options(tmp_path, sample=3), progress=False)
    results = tmp_path / "run" / RESULTS_FILE
    lines = results.read_bytes().splitlines(keepends=True)
    results.write_bytes(lines[0] + b"garbage\n" + lines[1][:50] + b"\n" + b"".join(lines[2:]))
    outcome = run_benchmark(options(tmp_path, sample=3), progress=False)
    assert (outcome.ran, outcome.skipped, outcome.interrupted) == (1, 5, False)
    assert len(outcome.notes) == 1
    assert "2 bad line(s) (line 2, 3" in outcome.notes[0]
    assert QUARANTINE_FILE in outcome.notes[0] and "run again" in outcome.notes[0]
    assert len(read_records(tmp_path / "run")) == 6
    entries = (tmp_path / "run" / QUARANTINE_FILE).read_text().splitlines()
    assert [json.loads(entry)["line"] for entry in entries] == [2, 3]
    assert run_benchmark(options(tmp_path, sample=3), progress=False).notes == []


def test_a_directory_does_not_mix_seeds_or_beliefs(tmp_path: Path) -> None:
    run_benchmark(options(tmp_path), progress=False)
    with pytest.raises(BenchError, match=r"seed 0 \(asked: 1\).*--rerun"):
        run_benchmark(options(tmp_path, seed=1), progress=False)
    with pytest.raises(BenchError, match=r"belief 'read' \(asked: 'faulty:0.1'\)"):
        run_benchmark(options(tmp_path, belief="faulty:0.1"), progress=False)
    outcome = run_benchmark(options(tmp_path, seed=1, rerun=True), progress=False)
    assert outcome.ran == 2


def test_a_crashing_method_gives_a_failed_record_and_the_run_goes_on(tmp_path: Path) -> None:
    outcome = run_benchmark(options(tmp_path, methods=["test-crash", "oracle"]), progress=False)
    assert outcome.ran == 4
    crashed = [r for r in outcome.records if r.method == "test-crash"]
    assert len(crashed) == 2
    assert all(not r.success and r.failure == "error: RuntimeError: boom" for r in crashed)
    assert all(r.execution_steps == 1 for r in crashed)  # the environment's count
    assert all(r.success for r in outcome.records if r.method == "oracle")


def test_success_is_judged_on_the_true_state_not_the_claim() -> None:
    record = run_one("test-liar", "true", 0, "kettle_1", "t01", "bundled")
    assert record.claimed_success and not record.success
    assert record.spl == 0.0 and record.execution_steps == 0
    assert "claimed success but goal not met" in record.failure


def test_too_many_reasoning_steps_is_a_failure_even_at_the_goal() -> None:
    record = run_one("test-overthink", "true", 0, "kettle_1", "t01", "bundled")
    assert not record.success and record.reasoning_steps == 26
    assert "reasoning-step limit (26 > 25)" in record.failure
    goal = cached_suite("bundled").get("kettle_1").tasks[0].goal
    assert len(record.final_values) == len(goal)  # the goal was reached all the same
    assert record.execution_steps == record.optimal_steps > 0  # counted by the environment


def test_workers_give_the_same_records_as_one_process(tmp_path: Path) -> None:
    chosen = ["oracle", "test-liar"]
    alone = run_benchmark(options(tmp_path, methods=chosen), progress=False)
    pooled = run_benchmark(
        options(tmp_path, methods=chosen, workers=2, out=tmp_path / "pool"), progress=False
    )
    strip = [r.model_dump(exclude={"timings"}) for r in alone.records]
    assert strip == [r.model_dump(exclude={"timings"}) for r in pooled.records]
    assert (tmp_path / "run" / "summary.json").read_bytes() == (
        tmp_path / "pool" / "summary.json"
    ).read_bytes()


@pytest.mark.parametrize(
    ("method", "name", "code"),
    [("test-interrupt", "SIGINT", 130), ("test-terminate", "SIGTERM", 143)],
)
def test_ctrl_c_and_sigterm_stop_cleanly_and_keep_finished_records(
    tmp_path: Path, method: str, name: str, code: int
) -> None:
    before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    outcome = run_benchmark(options(tmp_path, methods=["oracle", method]), progress=False)
    assert (outcome.interrupted, outcome.stopped_by, outcome.exit_code) == (True, name, code)
    assert outcome.ran == 2  # the first task of each method; the second appliance never started
    assert len(read_records(tmp_path / "run")) == 2
    assert (signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)) == before


def test_a_worker_that_dies_stops_the_run_and_keeps_what_finished(tmp_path: Path) -> None:
    outcome = run_benchmark(
        options(tmp_path, methods=["oracle", "test-die"], workers=2), progress=False
    )
    assert (outcome.interrupted, outcome.stopped_by, outcome.exit_code) == (
        True,
        WORKER_DIED,
        1,
    )
    kept = read_records(tmp_path / "run")
    assert sorted(r.key for r in kept) == [r.key for r in outcome.records]
    assert all(r.method == "oracle" and r.success for r in kept)
    again = run_benchmark(options(tmp_path, methods=["oracle"], workers=2), progress=False)
    assert (again.interrupted, again.ran + again.skipped) == (False, 2)


def test_beliefs() -> None:
    assert str(parse_belief(" faulty:0.50 ")) == "faulty:0.5"
    assert str(parse_belief("read")) == "read"
    for bad, message in (
        ("faulty:x", "not a number"),
        ("faulty:1.5", "between 0 and 1"),
        ("truth", "accepted: 'read', 'true'"),
    ):
        with pytest.raises(BeliefError, match=message):
            parse_belief(bad)
    appliance = cached_suite("bundled").get("kettle_1")
    assert belief_model(appliance, "true", 0) == (appliance.model, [])
    model, faults = belief_model(appliance, "faulty:1", 3)
    assert faults and model != appliance.model
    assert belief_model(appliance, "faulty:1", 3) == (model, faults)  # seeded
    read, notes = belief_model(appliance, "read", 0)  # no LLM configured: the offline reader
    assert notes == [] and read.appliance.name == "read from the manual"


def test_the_oracle_keeps_the_run_belief_but_plans_on_the_truth() -> None:
    record = run_one("oracle", "faulty:1", 0, "kettle_1", "t01", "bundled")
    assert record.belief == "faulty:1" and record.key == "oracle|faulty:1|kettle_1/t01"
    assert record.success and record.faults == []


def test_cli_rejects_an_unknown_method(tmp_path: Path) -> None:
    result = CliRunner().invoke(
        app, ["bench", "--methods", "oracle,apbot-openloop", "--out", str(tmp_path / "x")]
    )
    assert result.exit_code == 2
    assert "unknown method(s) apbot-openloop" in result.output
    assert "did you mean 'apbot-open-loop'" in result.output and "oracle" in result.output
    assert not (tmp_path / "x").exists()


def test_cli_runs_and_prints_the_table(tmp_path: Path) -> None:
    result = CliRunner().invoke(
        app,
        [
            "bench",
            "--methods",
            "oracle",
            "--appliances",
            "kettle_1",
            "--sample",
            "1",
            "--workers",
            "1",
            "--no-report",
            "--out",
            str(tmp_path / "x"),
        ],
    )
    assert result.exit_code == 0, result.output
    assert "oracle" in result.output and "1.00" in result.output and "kettle" in result.output


def test_two_runs_never_write_one_directory_at_once(tmp_path: Path) -> None:
    from apbot.bench.rundir import exclusive

    options = BenchOptions(
        methods=["oracle"], appliances=["kettle_1"], sample=1, workers=1, out=tmp_path / "run"
    )
    (tmp_path / "run").mkdir()
    with exclusive(tmp_path / "run"), pytest.raises(BenchError, match="another"):
        run_benchmark(options, progress=False)
    assert run_benchmark(options, progress=False).ran == 1  # free again afterwards


def _group_alive(group: int) -> list[int]:
    """Live (not zombie) processes of a process group, from /proc."""
    alive = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[2]) == group and fields[0] != "Z":
                alive.append(int(entry.name))
    return alive


def _kill_mid_run(command: list[str], out: Path, signum: int, log: Path) -> int:
    """Start ``command``, send ``signum`` to its main process alone once a new record exists
    (its workers are not signalled); the exit code, once no process of the run is left."""
    before = len(read_records(out)) if (out / RESULTS_FILE).exists() else 0
    with log.open("w") as stderr:
        process = subprocess.Popen(
            command, stdout=subprocess.DEVNULL, stderr=stderr, start_new_session=True
        )
        try:
            while not (out / RESULTS_FILE).exists() or len(read_records(out)) <= before:
                assert process.poll() is None, log.read_text()
                time.sleep(0.01)
            os.kill(process.pid, signum)
            code = process.wait(timeout=30)
            deadline = time.monotonic() + 5
            while _group_alive(process.pid) and time.monotonic() < deadline:
                time.sleep(0.02)
            assert not _group_alive(process.pid), "workers outlived the killed run"
        finally:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(process.pid, signal.SIGKILL)
    return code


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads /proc (Linux)")
def test_a_killed_bench_resumes_with_the_same_command(tmp_path: Path) -> None:
    """The README's advice, after `kill -9` and then after a plain `kill` of the main process."""
    out = tmp_path / "k"
    command = [sys.executable, "-m", "apbot.cli", "bench", "--methods", "oracle,apbot-open-loop"]
    command += ["--categories", "dehumidifier,kettle", "--sample", "3", "--workers", "2"]
    command += ["--no-report", "--out", str(out)]
    total = 2 * 10 * 3
    assert _kill_mid_run(command, out, signal.SIGKILL, tmp_path / "log") == -9
    first = len(read_records(out))  # the lock is free and the records are sound
    assert _kill_mid_run(command, out, signal.SIGTERM, tmp_path / "log") == 143
    last = (tmp_path / "log").read_text().strip().splitlines()[-1]
    assert "stopped (SIGTERM)" in last and "run the same command again to resume" in last
    kept = len(read_records(out))
    assert 0 < first < kept < total
    again = subprocess.run(command, capture_output=True, text=True, timeout=60)
    assert again.returncode == 0, again.stderr
    assert f"{total - kept} task(s) run, {kept} already finished" in again.stdout
    keys = [json.loads(line)["key"] for line in (out / RESULTS_FILE).read_text().splitlines()]
    assert len(keys) == len(set(keys)) == total
