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
