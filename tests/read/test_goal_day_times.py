"""A time of day on a model without a clock: a wrapping 24-hour dial of the day (00:00 to
23:xx) is when something happens (a watering start, a feeding time), so "at 6 in the evening"
sets it; a timer that counts up to 24:00 is a duration and takes no time of day. Checked on a
garden sprinkler controller and a plant-lamp timer written for these tests."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

SPRINKLER = """
appliance: {id: sprinkler_1, category: garden_sprinkler, name: "Rainette RC-4", brand: R}
controls:
  - {id: water_at_button, kind: button, label: "WATER AT"}
  - {id: minutes_button, kind: button, label: "MINUTES"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
  - {id: skip_button, kind: button, label: "SKIP RAIN"}
variables:
  water_at:
    type: time
    ranges: [["00:00:00", "23:30:00", 1800]]
    initial: "06:00:00"
    format: "hh:mm"
    wrap: true
  minutes:
    type: numeric
    unit: min
    ranges: [[5, 60, 5]]
    initial: 15
  rain_skip:
    type: discrete
    values: ["off", "on"]
actions:
  press_water_at: {control: water_at_button}
  press_minutes: {control: minutes_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_skip: {control: skip_button}
features:
  water_at:
    - {actions: [press_water_at], variable: water_at, effect: none}
    - {actions: [press_up], variable: water_at, effect: next}
    - {actions: [press_down], variable: water_at, effect: prev}
  minutes:
    - {actions: [press_minutes], variable: minutes, effect: none}
    - {actions: [press_up], variable: minutes, effect: next}
    - {actions: [press_down], variable: minutes, effect: prev}
  rain_skip:
    - {actions: [press_skip], variable: rain_skip, effect: toggle}
display:
  idle: ""
"""

LAMP = """
appliance: {id: lamp_1, category: plant_lamp, name: "Verda plant lamp", brand: V}
controls:
  - {id: timer_button, kind: button, label: "TIMER"}
variables:
  timer:
    type: time
    ranges: [["00:00:00", "24:00:00", 3600]]
    initial: "00:00:00"
    format: "hh:mm"
    wrap: true
actions:
  press_timer: {control: timer_button}
features:
  timer:
    - {actions: [press_timer], variable: timer, effect: next}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def sprinkler() -> ApplianceModel:
    return loads_model(SPRINKLER)


@pytest.mark.parametrize(
    ("text", "time"),
    [
        ("Water the lawn at 6 in the evening for 20 minutes", "18:00:00"),
        ("every day at half past five in the morning", "05:30:00"),
        ("Move watering to 9 pm and skip it when it rains", "21:00:00"),
        ("at midnight, 10 minutes", "00:00:00"),
        ("the watering time is 7:30", "07:30:00"),
    ],
)
def test_a_day_dial_without_a_clock_takes_a_time_of_day(
    sprinkler: ApplianceModel, text: str, time: str
) -> None:
    assert parse_instruction(sprinkler, text)["water_at"] == time


def test_a_duration_is_no_time_of_day(sprinkler: ApplianceModel) -> None:
    goal = parse_instruction(sprinkler, "Run it for 30 minutes")
    assert goal == {"minutes": 30}


def test_a_timer_up_to_24_hours_is_a_duration() -> None:
    lamp = loads_model(LAMP)
    assert parse_instruction(lamp, "Light for 14 hours")["timer"] == "14:00:00"
    assert "timer" not in parse_instruction(lamp, "Light at 7 in the morning")


def test_a_read_dial_that_does_not_say_it_wraps_is_still_the_day() -> None:
    """A reader seldom knows whether a dial wraps: a belief's FEED TIME 0:00-23:00 without
    ``wrap`` is still the hours of a day, and a duration still goes elsewhere."""
    read = loads_model(
        SPRINKLER.replace("    wrap: true\n", "", 1).replace('"23:30:00", 1800', '"23:00:00", 60')
    )
    assert parse_instruction(read, "Water at 10 pm for 20 minutes") == {
        "water_at": "22:00:00",
        "minutes": 20,
    }
    assert parse_instruction(read, "at midnight")["water_at"] == "00:00:00"


def test_a_read_timer_over_the_day_that_does_not_say_it_wraps_counts_down() -> None:
    """A read TIMER of 0:00-23:30 that does not say it wraps is a countdown by its name:
    "for 10 hours" sets it, "at 7 am" does not (a dial named a start or a time still is one)."""
    timer = loads_model(
        SPRINKLER.replace("    wrap: true\n", "", 1)
        .replace("  water_at:\n", '  water_at:\n    label: "OFF TIMER"\n', 1)
        .replace('initial: "06:00:00"', 'initial: "01:00:00"', 1)
    )
    assert parse_instruction(timer, "Water for 10 hours")["water_at"] == "10:00:00"
    assert "water_at" not in parse_instruction(timer, "Water at 7 in the morning")
