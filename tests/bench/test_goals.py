"""The goal a benchmark method gets: read from the instruction, or the stored one."""

from __future__ import annotations

import pytest

from apbot.bench.goals import GoalModeError, method_goal, parse_goal_mode, same_goal
from apbot.bench.runner import cached_suite


def test_goal_modes() -> None:
    assert parse_goal_mode("read") == "read" and parse_goal_mode(" given") == "given"
    with pytest.raises(GoalModeError, match="accepted: read, given"):
        parse_goal_mode("stored")


def test_a_read_goal_is_parsed_against_the_belief_and_judged_under_the_alignment() -> None:
    appliance = cached_suite("bundled").get("kettle_1")
    task = appliance.tasks[0]
    truth = appliance.model
    given = method_goal("given", truth, task.instruction, appliance.manual, task.goal, truth)
    assert given.goal == task.goal and given.parsed is None and given.exact is None
    read = method_goal("read", truth, task.instruction, appliance.manual, task.goal, truth)
    assert read.goal == read.parsed and read.exact is True and not read.error
    wrong = dict(task.goal, temperature=60)
    assert same_goal(truth, truth, read.parsed or {}, wrong) is False


def test_a_value_the_belief_lacks_is_handed_over_as_said_and_noted() -> None:
    appliance = cached_suite("bundled").get("kettle_1")
    task = appliance.tasks[0]
    asked = method_goal(
        "read", appliance.model, "Heat it to 120 degrees", "", task.goal, appliance.model
    )
    assert asked.goal == {"temperature": 120, "heating": "on"} and asked.exact is False
    assert asked.outside and asked.outside[0].startswith("'120 degrees': no setting")


def test_an_instruction_that_cannot_be_read_gives_no_goal_and_says_why() -> None:
    appliance = cached_suite("bundled").get("kettle_1")
    task = appliance.tasks[0]
    asked = method_goal("read", appliance.model, "x" * 6000, "", task.goal, appliance.model)
    assert asked.goal is None and asked.exact is False
    assert "cannot read the instruction" in asked.error and "characters" in asked.error
