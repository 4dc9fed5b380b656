"""A start word with "at" a time of day in its clause says when a schedule starts ("start
watering at 6 in the morning"), not a request to start now; "not now" holds the start back.
Checked on a garden sprinkler controller written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

SPRINKLER = """
appliance: {id: sprinkler_1, category: sprinkler, name: "Dew D1 sprinkler controller", brand: D}
controls:
  - {id: time_button, kind: button, label: "START TIME"}
  - {id: hour_button, kind: button, label: "HOUR"}
  - {id: run_button, kind: button, label: "RUN"}
variables:
  start_time:
    type: time
    ranges: [["00:00:00", "23:00:00", 3600]]
    format: "hh:mm"
    wrap: true
    label: "START"
  running:
    type: discrete
    values: ["off", "on"]
actions:
  press_time: {control: time_button}
  press_hour: {control: hour_button}
  press_run: {control: run_button}
features:
  start_time:
    - {actions: [press_time]}
    - {actions: [press_hour], variable: start_time, effect: {press_hour: next}}
  running:
    - {actions: [press_run], variable: running, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def sprinkler() -> ApplianceModel:
    return loads_model(SPRINKLER)


@pytest.mark.parametrize(
    "text",
    [
        "Start watering at 6 in the morning.",
        "Begin each day at 9 pm",
        "Have it start at noon every day",
    ],
)
def test_a_start_at_a_time_of_day_is_the_schedule(sprinkler: ApplianceModel, text: str) -> None:
    assert "running" not in parse_instruction(sprinkler, text)


def test_not_now_holds_the_start_back(sprinkler: ApplianceModel) -> None:
    goal = parse_instruction(sprinkler, "Start watering at 9 pm, not now.")
    assert goal.get("running") == "off"


def test_a_start_now_still_starts(sprinkler: ApplianceModel) -> None:
    assert parse_instruction(sprinkler, "Start watering now, at full flow.")["running"] == "on"


@pytest.mark.parametrize("text", ["Start watering and stop at 9 pm", "Begin and be done at 10 pm"])
def test_a_time_joined_on_to_another_verb_is_no_schedule(
    sprinkler: ApplianceModel, text: str
) -> None:
    """The time after "and stop" is when it stops: the start itself is now."""
    assert parse_instruction(sprinkler, text).get("running") == "on"
