"""--learn keeps a repaired belief only while it earns trust (``apbot.bench.memory``)."""

from __future__ import annotations

from typing import Any

import pytest

from apbot.bench import learn
from apbot.bench.records import TaskRecord
from apbot.bench.runner import RunSettings, WorkItem, _find, run_task_learning
from apbot.model.schema import ApplianceModel, Guard


def test_a_belief_that_blocks_the_goal_is_dropped_back_to_the_manuals_reading() -> None:
    appliance, task = _find("bundled", "kettle_1", "t01")  # heat to 80 degrees
    # a kept repair that was wrong: "while heating is off, START does nothing"
    wrong = appliance.model.model_copy(
        update={
            "guards": [Guard(when={"heating": "off"}, only=["press_temp", "press_warm"])],
        }
    )
    ApplianceModel.model_validate(wrong.model_dump())
    record, _after = run_task_learning(
        appliance, task, "apbot", "true", goal_mode="read", learnt=wrong, index=1
    )
    assert record.learnt_from == 0, record.failure  # started from the manual's reading
    assert record.success
    # a learnt belief that fits the request as well is kept
    record, _after = run_task_learning(
        appliance, task, "apbot", "true", goal_mode="read", learnt=appliance.model, index=1
    )
    assert record.learnt_from == 1 and record.success


def test_the_belief_of_an_episode_that_ended_in_failure_is_not_carried_on(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    appliance, _task = _find("bundled", "kettle_1", "t01")
    verdicts = iter([True, False, True, True])
    started: list[tuple[ApplianceModel | None, int]] = []

    def fake(
        item: WorkItem, settings: RunSettings, learnt: ApplianceModel | None, index: int
    ) -> tuple[TaskRecord, Any]:
        started.append((learnt, index))
        record = TaskRecord.model_construct(
            task=item.task, claimed_success=next(verdicts), learnt_from=index if learnt else 0
        )
        return record, appliance.model

    monkeypatch.setattr(learn, "run_item", fake)
    items = [WorkItem("apbot", "kettle_1", f"t0{i}") for i in range(1, 5)]
    list(learn.run_chain(items, RunSettings(learn=True)))
    # t02 starts from t01's belief; t02 failed, so t03 starts from the manual's reading again
    assert [(m is not None, i) for m, i in started] == [
        (False, 0),
        (True, 1),
        (False, 0),
        (True, 1),
    ]
