"""Replaying run.json's selection: exact keys from the suite, else the count run.json keeps."""

from __future__ import annotations

from apbot.bench.records import record_key
from apbot.bench.report.selection import replay_selection
from tests.bench.report.rundir import RUN, record


def test_the_selection_is_replayed_on_the_suite_to_the_exact_keys() -> None:
    selection = replay_selection(RUN)
    assert selection.methods == ("oracle", "apbot") and selection.tasks == 2
    assert selection.keys == {
        record_key(m, "true", a, "t01")
        for m in ("oracle", "apbot")
        for a in ("kettle_1", "dehumidifier_1")
    }
    assert selection.appliances == {"kettle_1": 1, "dehumidifier_1": 1}
    assert selection.note == ""
    assert selection.includes(record("apbot", "kettle_1", "t01", True))
    assert not selection.includes(record("apbot", "kettle_1", "t02", True))


def test_a_suite_that_cannot_be_loaded_leaves_the_count_of_run_json() -> None:
    selection = replay_selection({**RUN, "suite": "/no/such/suite"})
    assert selection.tasks == 2 and selection.keys is None and not selection.appliances
    assert "could not be replayed on suite '/no/such/suite'" in selection.note
    assert selection.includes(record("apbot", "kettle_1", "t02", True))  # cannot tell
    assert not selection.includes(record("apbot-open-loop", "kettle_1", "t01", True))


def test_a_suite_that_changed_since_the_run_is_noticed() -> None:
    selection = replay_selection({**RUN, "tasks": 6})
    assert selection.tasks == 3 and selection.keys is None
    assert selection.note == (
        "the suite now selects 4 (method, task) pairs where run.json says 6: it changed "
        "since the run"
    )


def test_without_methods_or_counts_nothing_is_expected() -> None:
    assert replay_selection({}).tasks is None
    unknown = replay_selection({"methods": ["apbot"], "belief": "true"})
    assert unknown.tasks is None and unknown.methods == ("apbot",)
    assert "does not record the suite and selection" in unknown.note
