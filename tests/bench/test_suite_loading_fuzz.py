"""Fuzz the suite loader: a mutated suite directory loads, or is one SuiteError naming files
and lines; a suite that loads validates to a list of problems. Never a crash, never a hang."""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

from hypothesis import event, given
from hypothesis import strategies as st

from apbot.bench.suite import (
    APPLIANCE_FILES,
    MANUAL_FILES,
    SuiteError,
    bundled_suite_dir,
    load_suite,
    validate_suite,
)
from tests.fuzz import fuzz_settings, mutated_data_text, mutated_text, no_hang

SOURCES = ["dehumidifier_1", "kettle_2"]
FILES = [*APPLIANCE_FILES, "manual.md"]


@st.composite
def damage(draw: st.DrawFn) -> tuple[str, str, str | bytes | None]:
    """(appliance, file, new content): text or data mutations, bytes, or None to delete."""
    appliance = draw(st.sampled_from(SOURCES))
    name = draw(st.sampled_from(FILES))
    path = bundled_suite_dir() / appliance / name
    original = path.read_text(encoding="utf-8") if path.exists() else ""
    kind = draw(st.sampled_from(["text", "data", "data", "bytes", "delete", "empty", "dir"]))
    if kind == "text":
        return appliance, name, draw(mutated_text(original))
    if kind == "data" and name.endswith(".yaml"):
        return appliance, name, draw(mutated_data_text(original))
    if kind == "bytes":
        return appliance, name, draw(st.binary(max_size=64))
    if kind == "empty":
        return appliance, name, ""
    if kind == "dir":
        return appliance, name, "<dir>"
    return appliance, name, None


def remove(path: Path) -> None:
    if path.is_dir():
        shutil.rmtree(path)
    else:
        path.unlink(missing_ok=True)


def apply(root: Path, appliance: str, name: str, content: str | bytes | None) -> None:
    target = root / appliance / name
    for old in MANUAL_FILES if name == "manual.md" else [name]:  # one manual per appliance
        remove(root / appliance / old)
    if content == "<dir>":
        target.mkdir()
    elif isinstance(content, bytes):
        target.write_bytes(content)
    elif content is not None:
        target.write_text(content, encoding="utf-8")


@fuzz_settings(40)
@given(st.lists(damage(), min_size=1, max_size=3))
def test_a_damaged_suite_loads_or_names_each_broken_file(
    damages: list[tuple[str, str, str | bytes | None]],
) -> None:
    with tempfile.TemporaryDirectory() as scratch:
        root = Path(scratch)
        for appliance in SOURCES:
            shutil.copytree(bundled_suite_dir() / appliance, root / appliance)
        for appliance, name, content in damages:
            apply(root, appliance, name, content)
        try:
            with no_hang("loading a suite"):
                suite = load_suite(root)
        except SuiteError as exc:
            event(f"refused: {exc.problems[0].check}")
            assert exc.problems
            for problem in exc.problems:
                assert problem.source and problem.source.startswith(scratch), problem
                assert "\n" not in problem.render(), problem
            return
        with no_hang("validating a suite"):
            problems = validate_suite(suite)
        event("validated: " + ("problems" if problems else "clean"))
        for problem in problems:
            assert problem.source and "\n" not in problem.render(), problem
