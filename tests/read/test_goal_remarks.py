"""Remarks around an instruction (a user's day, people, places to put the food) ask nothing of
the appliance: the goal parser reads the same goal with or without them, and still reads a
setting said after a comma ("start in 3 hours"). A small steamer manual in our own words."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.goal import parse_instruction

STEAMER = """# Grain steamer GS-7

## Keys
| Key | Function |
|---|---|
| POWER | Switches the steamer on or off. |
| MENU | Chooses the programme: WHITE, BROWN or PORRIDGE. |
| HEAT | Chooses the steam heat: LOW or HIGH. |
| TIME | Sets the cooking time, 5 to 90 minutes, in steps of 5 minutes, with + and -. |
| DELAY | Sets the delay before cooking starts, 1 to 12 hours, with + and -. |
| + | Raises the value shown. |
| - | Lowers the value shown. |
| START | Starts cooking. |
"""
ACTIONS = [
    "press_power",
    "press_menu",
    "press_heat",
    "press_time",
    "press_delay",
    "press_plus",
    "press_minus",
    "press_start",
]


def read(instruction: str) -> dict[str, object]:
    model = read_manual(STEAMER, ACTIONS).model
    return dict(parse_instruction(model, instruction, STEAMER, outside=[]))


def test_a_clause_about_the_user_or_others_changes_nothing() -> None:
    base = "Brown rice on low heat for 40 minutes"
    goal = read(base)
    for remark in (
        ", my kids are 5 and 7",
        ", the last one took 20 minutes",
        ", dinner is at 7",
        " and we'll be home in 2 hours",
        "; we are 4 at the table",
        " — my old one had 3 settings",
    ):
        assert read(base + remark) == goal, remark


def test_a_time_from_now_after_back_is_no_cooking_time() -> None:
    assert "time" not in read("Porridge please, I'll be back in 10 minutes")
    assert "delay" not in read("White rice, I'll be back in an hour")


def test_putting_the_food_somewhere_is_no_heat_level() -> None:
    assert "heat" not in read("Porridge for 20 minutes - put the bowl on the lower shelf")
    assert read("White rice, put the heat on high")["heat"] == "high"


def test_a_setting_after_a_comma_is_still_read() -> None:
    assert read("Brown rice on low heat, start in 3 hours")["delay"] == 3
    assert read("Porridge, I want it ready in 3 hours")["delay"] == 3
    assert read("White rice; it should be done in 2 hours")["delay"] == 2


def test_a_remark_in_brackets_or_its_own_sentence_changes_nothing() -> None:
    base = "Brown rice on low heat for 40 minutes"
    assert read("Brown rice on low heat (it's my 3rd try) for 40 minutes") == read(base)
    assert read(base + ". We leave in 2 hours.") == read(base)
    assert read("Porridge (the small pot) for 20 minutes")["time"] == "00:20:00"
