"""What produced a run: the code version (with or without git) and the suite's digest; a run
directory resumes only with both unchanged."""

from __future__ import annotations

import dataclasses
import json
import shutil
import subprocess
from pathlib import Path

import pytest

import apbot
from apbot.bench import provenance, runner, task_run
from apbot.bench.provenance import code_version, describe_code, same_code, suite_digest
from apbot.bench.runner import BenchError, BenchOptions, cached_suite, run_benchmark
from apbot.bench.suite import Suite, bundled_suite_dir

version_of = code_version.__wrapped__  # uncached, for packages made by the tests
needs_git = pytest.mark.skipif(shutil.which("git") is None, reason="needs git")


def git(directory: Path, *arguments: str) -> str:
    command = ["git", "-C", str(directory), "-c", "user.name=t", "-c", "user.email=t@t"]
    return subprocess.run(
        [*command, *arguments], check=True, capture_output=True, text=True
    ).stdout.strip()


def package_in(directory: Path) -> Path:
    package = directory / "apbot"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("")
    return package


def test_outside_a_repository_there_is_a_version_and_no_revision(tmp_path: Path) -> None:
    version = version_of(package_in(tmp_path))
    assert version == {
        "apbot": apbot.__version__,
        "source": version["source"],
        "git": None,
        "git_dirty": None,
    }
    assert version["source"].startswith("sha256:")


def test_an_edited_copy_without_git_is_another_version(tmp_path: Path) -> None:
    """A copy made by ``git archive`` (or an installed one) has no revision: only the source
    digest tells two states of its code apart, so their results never mix in one run."""
    package = package_in(tmp_path)
    before = version_of(package)
    (package / "__init__.py").write_text("# changed\n")
    after = version_of(package)
    assert after["git"] is None and after["source"] != before["source"]
    assert not same_code(before, after)
    assert same_code(after, version_of(package))
    assert describe_code(after) == f"apbot {apbot.__version__} (source {after['source'][7:19]})"


def test_without_git_there_is_no_revision_and_no_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PATH", str(tmp_path / "nowhere"))
    assert version_of(Path(apbot.__file__).parent)["git"] is None


@needs_git
def test_the_revision_is_that_of_the_repository_tracking_the_package(tmp_path: Path) -> None:
    package = package_in(tmp_path)
    git(tmp_path, "init", "-q")
    assert version_of(package)["git"] is None  # in a repository that does not track it
    git(tmp_path, "add", ".")
    git(tmp_path, "commit", "-qm", "x")
    head = git(tmp_path, "rev-parse", "HEAD")
    clean = version_of(package)
    assert clean == {
        "apbot": apbot.__version__,
        "source": clean["source"],
        "git": head,
        "git_dirty": False,
    }
    (package / "__init__.py").write_text("# changed\n")
    assert version_of(package)["git_dirty"] is True
    assert not same_code(clean, version_of(package))  # an edited working tree does not resume
    assert describe_code(version_of(package)) == f"apbot {apbot.__version__} (git {head[:12]})"


def test_the_suite_digest_follows_models_tasks_and_manuals() -> None:
    bundled = cached_suite("bundled")
    kettle = bundled.get("kettle_1")

    def digest(**changes: object) -> str:
        return suite_digest(
            Suite("x", Path("."), [dataclasses.replace(kettle, **changes)])  # type: ignore[arg-type]
        )

    same = digest()
    assert same == digest() and same.startswith("sha256:")
    assert digest(manual=kettle.manual + "\nOne more sentence.") != same
    task = kettle.tasks[0].model_copy(update={"optimal_steps": 99})
    assert digest(tasks=[task, *kettle.tasks[1:]]) != same
    assert digest(tasks=kettle.tasks[1:]) != same
    assert digest(model=bundled.get("kettle_2").model) != same
    assert suite_digest(bundled) != same


def _options(out: Path, **changes: object) -> BenchOptions:
    base = BenchOptions(methods=["oracle"], appliances=["kettle_1"], sample=1, workers=1, out=out)
    return dataclasses.replace(base, **changes)  # type: ignore[arg-type]


def test_another_code_version_does_not_resume_the_directory(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    run_benchmark(_options(tmp_path / "run"), progress=False)
    now = code_version()
    other = {**now, "apbot": "9.9.9", "git": "f" * 40}
    monkeypatch.setattr(runner, "code_version", lambda: other)
    with pytest.raises(BenchError) as raised:
        run_benchmark(_options(tmp_path / "run"), progress=False)
    message = str(raised.value)
    assert f"written by {describe_code(now)} and this is apbot 9.9.9 (git ffffffffffff)" in message
    assert "--rerun" in message
    assert run_benchmark(_options(tmp_path / "run", rerun=True), progress=False).ran == 1


def test_another_state_of_the_suite_does_not_resume_the_directory(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    suite = tmp_path / "suite"
    shutil.copytree(bundled_suite_dir() / "kettle_1", suite / "kettle_1")
    options = _options(tmp_path / "run", suite=str(suite))
    first = run_benchmark(options, progress=False)
    assert first.ran == 1
    manual = suite / "kettle_1" / "manual.md"
    manual.write_text(manual.read_text() + "\nDescale it monthly.\n")
    monkeypatch.setattr(task_run, "_SUITES", {})  # as a new process would: load it again
    with pytest.raises(BenchError, match=r"its suite digest is sha256:\w+… and the suite's is now"):
        run_benchmark(options, progress=False)
    assert run_benchmark(dataclasses.replace(options, rerun=True), progress=False).ran == 1


def test_run_json_records_the_code_and_the_suite(tmp_path: Path) -> None:
    run_benchmark(_options(tmp_path / "run"), progress=False)
    recorded = json.loads((tmp_path / "run" / "run.json").read_text())
    assert recorded["code"] == code_version()
    assert recorded["suite_digest"] == provenance.suite_digest(cached_suite("bundled"))
