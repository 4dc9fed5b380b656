"""The command line: exit codes and messages a user (or a script) relies on."""

from __future__ import annotations

from pathlib import Path

import pytest
from rich.console import Console
from typer.testing import CliRunner

from apbot.cli import app

runner = CliRunner()


def test_check_a_good_model() -> None:
    result = runner.invoke(app, ["check", "washing_machine"])
    assert result.exit_code == 0, result.output
    assert "ok" in result.output


def test_check_a_bad_model_names_path_and_line(tmp_path: Path) -> None:
    from apbot.examples import example_dir

    text = (example_dir() / "washing_machine.yaml").read_text()
    bad = tmp_path / "bad.yaml"
    bad.write_text(text.replace("actions: [press_rinse]", "actions: [press_rinser]"))
    result = runner.invoke(app, ["check", str(bad)])
    assert result.exit_code == 1
    assert "features.extra_rinse[0].actions[0]" in result.output
    assert "did you mean 'press_rinse'" in result.output
    assert f"{bad}:" in result.output and "Traceback" not in result.output


def test_check_runs_the_model_for_a_lock_that_never_opens(tmp_path: Path) -> None:
    from apbot.examples import example_dir

    text = (example_dir() / "washing_machine.yaml").read_text()
    old = "{actions: [hold_temp_and_spin], variable: child_lock, effect: toggle}"
    assert old in text
    bad = tmp_path / "locked.yaml"
    bad.write_text(text.replace(old, old.replace("toggle", '{to: "on"}')))
    result = runner.invoke(app, ["check", str(bad)])
    assert result.exit_code == 1, result.output
    assert "guard 'child lock' holds for good" in " ".join(result.output.split())


def test_check_broken_yaml(tmp_path: Path) -> None:
    bad = tmp_path / "broken.yaml"
    bad.write_text("appliance: {id: x\ncontrols: [\n")
    result = runner.invoke(app, ["check", str(bad)])
    assert result.exit_code == 1
    assert "YAML syntax" in result.output and "Traceback" not in result.output


def test_check_a_goal() -> None:
    result = runner.invoke(app, ["check", "washing_machine", "-g", "programme=wol"])
    assert result.exit_code == 1
    assert "did you mean 'wool'" in result.output


def test_plan_prints_a_table() -> None:
    result = runner.invoke(
        app,
        ["plan", "washing_machine", "-g", "power=on", "-g", "programme=wool", "-g", "running=on"],
    )
    assert result.exit_code == 0, result.output
    assert "select_programme" in result.output and "turn_programme_cw ×4" in result.output


def test_plan_json_and_unreachable() -> None:
    result = runner.invoke(app, ["plan", "microwave_keypad", "-g", "clock=9:45", "--json"])
    assert result.exit_code == 0 and '"press_9"' in result.output
    result = runner.invoke(app, ["plan", "microwave_keypad", "-g", "power_level=50"])
    assert result.exit_code == 1 and "50 is not one of its values" in result.output


def test_sim_script(tmp_path: Path) -> None:
    script = tmp_path / "actions.txt"
    script.write_text(
        "press_power\nturn_programme_cw\npress_temp\nnonsense\nhold_temp_and_spin 1\nstate\n"
    )
    result = runner.invoke(app, ["sim", "washing_machine", "--script", str(script)])
    assert result.exit_code == 0, result.output
    assert "PRG eco 40-60" in result.output
    assert "unknown action 'nonsense'" in result.output
    assert "must be held for 3 s" in result.output


def test_unknown_model_is_a_clear_error() -> None:
    result = runner.invoke(app, ["plan", "no_such_thing", "-g", "a=b"])
    assert result.exit_code == 1 and "not a model file" in result.output


def test_bad_inputs_are_messages_not_tracebacks(tmp_path: Path) -> None:
    binary = tmp_path / "model.yaml"
    binary.write_bytes(b"\xff\xfe\x00bad")
    result = runner.invoke(app, ["check", str(binary)])
    assert result.exit_code == 1 and "not UTF-8" in result.output
    result = runner.invoke(app, ["sim", "washing_machine", "--script", str(tmp_path / "none")])
    assert result.exit_code == 1 and "cannot read the script" in result.output
    result = runner.invoke(
        app, ["plan", "washing_machine", "-g", "programme=wool", "-g", "programme=cotton"]
    )
    assert result.exit_code == 1 and "given twice" in result.output
    result = runner.invoke(app, ["plan", "microwave_keypad", "-g", "cook_time=00:75:00"])
    assert result.exit_code == 1 and "not a time" in result.output
    for result in (runner.invoke(app, ["check", str(tmp_path)]),):
        assert "Traceback" not in result.output


def test_run_shows_a_task_live_and_judges_it() -> None:
    # a belief that prints a setting wrong: seen, repaired, done (microwave_3's cooking time
    # labelled "COOK TIME" for the panel's "TIME" is now read as it is, with no repair)
    result = runner.invoke(app, ["run", "bread_maker_1", "t01", "--belief", "faulty:0.3:display"])
    assert result.exit_code == 0, result.output
    assert "✗ mismatch" in result.output and "repair:" in result.output
    assert "success:" in result.output and "SPL" in result.output
    # an instruction the appliance cannot do: a declared failure, exit 1
    impossible = runner.invoke(app, ["run", "kettle_1", "x", "-g", "temperature=81"])
    assert impossible.exit_code != 0 and "Traceback" not in impossible.output


def test_run_with_an_explicit_goal_and_a_failure_exit_code() -> None:
    ok = runner.invoke(
        app, ["run", "kettle_1", "keep it warm at 80", "-g", "keep_warm=on", "-g", "temperature=80"]
    )
    assert ok.exit_code == 0, ok.output
    impossible = runner.invoke(app, ["run", "kettle_1", "Heat the water to 120 degrees"])
    assert impossible.exit_code == 2, impossible.output
    assert "cannot read the instruction: '120 degrees'" in " ".join(impossible.output.split())


def test_run_reads_any_instruction_and_says_it_reads_offline() -> None:
    free = runner.invoke(
        app, ["run", "kettle_1", "Warm the water to 80 degrees, please", "--belief", "true"]
    )
    text = " ".join(free.output.split())
    assert "no LLM is configured" in text and "--llm local" in text and "APBOT_LLM" in text
    assert "read goal: temperature=80, heating=on" in text, free.output
    assert "the agent's verdict" in text and free.exit_code == 0, free.output
    task = runner.invoke(app, ["run", "kettle_1", "t01", "--belief", "true"])
    text = " ".join(task.output.split())
    assert "stored goal:" in text and "read goal:" in text and "SPL" in text, task.output


def test_run_names_an_unknown_method_for_a_task_and_for_a_free_instruction() -> None:
    # a free instruction once raised a bare KeyError (found by the command-line fuzz)
    for words in (["t01"], ["make tea"]):
        result = runner.invoke(app, ["run", "kettle_1", *words, "--method", "nosuch"])
        text = " ".join(result.output.split())
        assert result.exit_code == 2 and "unknown method 'nosuch'" in text, result.output
        assert "apbot-open-loop" in text  # the known methods are listed
        assert not isinstance(result.exception, KeyError), result.exception


def test_run_a_free_instruction_through_the_rendered_panel() -> None:
    """`--feedback image` on an instruction that is no task: the panel photo is grounded and the
    presses land on it, as in `bench` (it once crashed: the simulator refused image mode)."""
    seen = runner.invoke(
        app,
        ["run", "kettle_1", "Warm the water to 80", "--belief", "true", "--feedback", "image"],
    )
    text = " ".join(seen.output.split())
    assert seen.exception is None or isinstance(seen.exception, SystemExit), seen.exception
    assert "read goal: temperature=80, heating=on" in text, seen.output
    assert "the agent's verdict" in text, seen.output


def test_report_on_a_directory_without_a_run_is_a_clear_error(tmp_path: Path) -> None:
    result = runner.invoke(app, ["report", str(tmp_path)])
    assert result.exit_code == 1 and "apbot bench" in result.output


def test_report_on_a_partial_run_says_how_far_it_got(tmp_path: Path) -> None:
    from tests.bench.report.rundir import write_run

    write_run(tmp_path, [])
    result = runner.invoke(app, ["report", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert "partial run: 0 of 2 tasks finished per method" in result.output


def test_run_a_task_id_with_its_own_goal() -> None:
    result = runner.invoke(app, ["run", "microwave_1", "t03", "-g", "clock=5:00"])
    assert result.exit_code == 0, result.output
    assert "goal: clock=5:00" in result.output


def test_run_takes_any_instruction_with_a_goal_and_checks_the_goal_first() -> None:
    short = runner.invoke(app, ["run", "kettle_1", "x", "-g", "temperature=80"])
    assert short.exit_code == 0, short.output
    assert "pydantic" not in short.output and "kettle_1 · x" in short.output
    bad = runner.invoke(app, ["run", "kettle_1", "x", "-g", "temperature=81"])
    assert bad.exit_code == 2
    assert bad.output.strip() == (
        "error: goal.temperature: 81°C is not one of its values (40, 50, 60, 70, ..., 100)"
    )


def test_run_loads_only_the_appliance_it_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    def whole_suite(*args: object, **kwargs: object) -> None:
        raise AssertionError("apbot run loaded the whole suite")

    monkeypatch.setattr("apbot.bench.suite.load_suite", whole_suite)
    result = runner.invoke(app, ["run", "dehumidifier_1", "t01"])
    assert result.exit_code == 0, result.output
    unknown = runner.invoke(app, ["run", "dehumidifer_1", "t01"])
    assert unknown.exit_code == 2 and "did you mean 'dehumidifier_1'?" in unknown.output


@pytest.mark.parametrize("width", [80, 40])
def test_suite_list_never_cuts_an_id(monkeypatch: pytest.MonkeyPatch, width: int) -> None:
    from apbot import cli_suite
    from apbot.bench.suite import load_suite

    monkeypatch.setattr(cli_suite, "console", Console(width=width, highlight=False, soft_wrap=True))
    result = runner.invoke(app, ["suite", "list"])
    assert result.exit_code == 0, result.output
    first_column = {line.split()[0] for line in result.output.splitlines() if line.strip()}
    ids = {a.id for a in load_suite().appliances}
    assert ids <= first_column, sorted(ids - first_column)
    assert "…" not in result.output


def test_bench_help_advertises_the_read_belief_and_goal_as_defaults() -> None:
    result = runner.invoke(app, ["bench", "--help"])
    assert result.exit_code == 0
    text = " ".join(result.output.replace("│", " ").split())
    belief = text.split("--belief", 1)[1].split("--goal", 1)[0]
    assert "faulty:RATE" in belief and "read" in belief and "[default: read]" in belief
    goal = text.split("--goal", 1)[1].split("--learn", 1)[0]
    assert "given" in goal and "[default: read]" in goal
