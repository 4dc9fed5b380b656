"""Read beliefs: read once per appliance, cached by manual, actions and reader version."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import apbot.read
from apbot.bench.beliefs import belief_model
from apbot.bench.reading import (
    belief_differences,
    cache_dir,
    cache_key,
    model_digest,
    read_belief,
    reader_version,
)
from apbot.bench.runner import cached_suite


@pytest.fixture()
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("APBOT_CACHE_DIR", str(tmp_path))
    return tmp_path


def _count_reads(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    calls: list[int] = []
    real = apbot.read.read_manual

    def counting(*args: object, **kwargs: object) -> apbot.read.Reading:
        calls.append(1)
        return real(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(apbot.read, "read_manual", counting)
    return calls


def test_a_manual_is_read_once_and_then_taken_from_disk(
    cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    appliance = cached_suite("bundled").get("kettle_2")
    actions = list(appliance.model.actions)
    calls = _count_reads(monkeypatch)
    first = read_belief(appliance.manual, actions, appliance.id, appliance.category)
    again = read_belief(appliance.manual, actions, appliance.id, appliance.category)
    assert len(calls) == 1 and first.model == again.model and first.digest == again.digest
    assert first.digest == model_digest(first.model) and first.digest.startswith("sha256:")
    assert len(list((cache / "read").glob("*.json"))) == 1
    # another action list, another manual: another key, read again
    read_belief(appliance.manual, actions[:-1], appliance.id, appliance.category)
    read_belief(
        appliance.manual + "\nPress LOCK to lock.", actions, appliance.id, appliance.category
    )
    assert len(calls) == 3


def test_the_key_covers_manual_actions_labels_and_reader_version() -> None:
    base = cache_key("m", ["a", "b"], "x", "c")
    assert base != cache_key("m2", ["a", "b"], "x", "c")
    assert base != cache_key("m", ["b", "a"], "x", "c")
    assert base != cache_key("m", ["a", "b"], "y", "c")
    assert len(reader_version()) == 16 and base == cache_key("m", ["a", "b"], "x", "c")


def test_the_reader_version_follows_the_model_package_and_the_goal_modules(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An edit to the model's unit table or to the goal parser's stemmer (both of which the reader
    borrows) reads the manuals again."""
    import shutil

    import apbot.model

    copies = {}
    for package in (apbot.read, apbot.model):
        source = Path(package.__file__).resolve().parent
        copy = tmp_path / "apbot" / source.name
        shutil.copytree(source, copy, ignore=shutil.ignore_patterns("__pycache__"))
        monkeypatch.setattr(package, "__file__", str(copy / "__init__.py"))
        copies[source.name] = copy

    def version() -> str:
        reader_version.cache_clear()
        return reader_version()

    monkeypatch.setattr("apbot.bench.reading.reader_version", reader_version)
    before = version()
    assert version() == before
    units = copies["model"] / "values.py"
    units.write_text(units.read_text() + "\n# a new unit\n")
    after_units = version()
    assert after_units != before
    stemmer = copies["read"] / "goal_vocab.py"
    stemmer.write_text(stemmer.read_text() + "\n# a new stem\n")
    assert version() not in (before, after_units)
    reader_version.cache_clear()


def test_a_damaged_cache_entry_is_read_again(cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    appliance = cached_suite("bundled").get("microwave_1")
    actions = list(appliance.model.actions)
    first = read_belief(appliance.manual, actions, appliance.id, appliance.category)
    (entry,) = (cache / "read").glob("*.json")
    entry.write_text('{"model": {"appliance": 3}}')
    calls = _count_reads(monkeypatch)
    again = read_belief(appliance.manual, actions, appliance.id, appliance.category)
    assert calls == [1] and again.model == first.model
    assert json.loads(entry.read_text())["model"]["appliance"]["id"] == "microwave_1"


def test_the_cache_can_be_turned_off(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("APBOT_CACHE_DIR", "off")
    assert cache_dir() is None
    calls = _count_reads(monkeypatch)
    appliance = cached_suite("bundled").get("kettle_1")
    for _ in range(2):
        read_belief(appliance.manual, list(appliance.model.actions))
    assert len(calls) == 2


def test_the_read_belief_is_a_belief_and_differences_are_judged_on_the_truth() -> None:
    appliance = cached_suite("bundled").get("blender_1")
    model, faults = belief_model(appliance, "read", 0)
    assert faults == [] and set(model.actions) == set(appliance.model.actions)
    assert belief_differences(appliance.model, appliance.model) == []
    differences = belief_differences(model, appliance.model)
    assert differences and all(isinstance(line, str) for line in differences)
