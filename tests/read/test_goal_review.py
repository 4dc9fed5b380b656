"""Regressions a review found in the goal rules of the days-and-levels round: each sentence is
written for these tests, on the proofing cabinet of test_goal_general (no suite has one)."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from tests.read.test_goal_general import CABINET

_MODES = "values: [dough, yogurt, tempeh, cheese]"


def test_a_choice_list_from_off_is_no_scale_of_strength() -> None:
    """A programme list that opens with OFF names things, not amounts: no "strongest" end."""
    model = loads_model(CABINET.replace(_MODES, 'values: ["off", dough, yogurt, tempeh, cheese]'))
    for text in ("Use the strongest mode", "Pick the longest mode"):
        try:
            goal = parse_instruction(model, text)
        except ValueError:
            continue  # refused: no mode is the strongest
        assert goal.get("mode") != "cheese"
    # the level setting of the same shape still is a scale
    assert parse_instruction(model, "Dough, the maximum mist")["mist"] == "heavy"


def test_start_this_or_next_thing_is_a_start_now() -> None:
    model = loads_model(CABINET)
    assert parse_instruction(model, "Start this batch on yogurt.")["running"] == "on"
    assert parse_instruction(model, "Start the next batch on cheese.")["running"] == "on"
    assert "running" not in parse_instruction(model, "Yogurt, starting next week.")


def test_a_negated_verb_near_a_level_does_not_turn_it_off() -> None:
    model = loads_model(CABINET)
    assert "mist" not in parse_instruction(model, "Dough; don't touch the mist, just start.")
    assert parse_instruction(model, "Dough with no mist")["mist"] == "off"


def test_waiting_for_something_else_does_not_hold_back_the_start() -> None:
    model = loads_model(CABINET)
    assert (
        parse_instruction(model, "Start the dough; I'll wait before shaping it.")["running"] == "on"
    )
    assert parse_instruction(model, "Dough, but hold off on starting")["running"] == "off"


def test_how_often_is_no_duration() -> None:
    model = loads_model(CABINET)
    goal = parse_instruction(model, "Yogurt, I make it twice a week")
    assert goal["mode"] == "yogurt" and "ferment_days" not in goal
    assert "ferment_days" not in parse_instruction(model, "Cheese, three times a week")


def test_weeks_are_left_alone_without_a_setting_counted_in_days() -> None:
    hours = CABINET.replace(
        "unit: d\n    ranges: [[1, 30, 1]]", "unit: h\n    ranges: [[1, 48, 1]]"
    )
    goal = parse_instruction(loads_model(hours), "Tempeh, and start it; back in a week")
    assert goal["mode"] == "tempeh" and "ferment_days" not in goal


def test_a_level_word_joined_to_speed_still_names_the_level() -> None:
    model = loads_model(CABINET.replace("values: [low, medium, high]", "values: [low, high]"))
    assert parse_instruction(model, "Dough with the fan on high-speed")["fan"] == "high"
    assert parse_instruction(model, "Yogurt on a low-speed fan")["fan"] == "low"
    assert "fan" not in parse_instruction(model, "Yogurt from low-fat milk")


def test_switching_off_as_a_later_step_is_no_power_off_now() -> None:
    model = loads_model(CABINET)
    goal = parse_instruction(model, "Ferment the dough, then switch the cabinet off.")
    assert goal["mode"] == "dough" and goal.get("power") != "off"
    assert parse_instruction(model, "Turn it off")["power"] == "off"


def test_holding_off_on_a_switch_is_that_switch_off_not_the_start() -> None:
    model = loads_model(CABINET)
    goal = parse_instruction(model, "Start the dough, hold off on auto stop.")
    assert goal["running"] == "on" and goal.get("auto_stop") == "off"


def test_a_negated_verb_of_handling_leaves_a_number_as_it_is() -> None:
    """ "without touching the days" keeps the count as it is; "no days" zeroes it."""
    model = loads_model(CABINET.replace("ranges: [[1, 30, 1]]", "ranges: [[0, 30, 1]]"))
    for text in (
        "Tempeh, without touching the ferment days",
        "Tempeh; don't change the ferment days",
        "Tempeh without adjusting the days",
    ):
        assert "ferment_days" not in parse_instruction(model, text), text
    assert parse_instruction(model, "Tempeh with no ferment days")["ferment_days"] == 0
    assert parse_instruction(model, "Tempeh without using the ferment days")["ferment_days"] == 0
    assert "mist" not in parse_instruction(model, "Dough without changing the mist")
