"""Kinds of saying a setting that the new categories showed, each checked on models written for
these tests (a seedling grow light with a heat mat, a rowing machine): two times of day said
as a span, a percentage on levels listed without "%", a superlative that names its own kind
(warmest, as long as it allows), and one figure whose meaning a mode gives (minutes,
kilometres or calories)."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction
from apbot.read.number_tokens import tokenize
from apbot.read.numbers import find_mentions

from .goal_kind_models import GROW_LIGHT


@pytest.mark.parametrize(
    ("sentence", "start", "end"),
    [
        ("Keep the seedlings lit from 6 am until 8 pm.", "06:00:00", "20:00:00"),
        ("Light them between 5:30 and 21:00 please.", "05:30:00", "21:00:00"),
        ("Lamps on at 6:30 am and off at 10 at night.", "06:30:00", "22:00:00"),
        ("Run it from 9 in the morning to 7 in the evening.", "09:00:00", "19:00:00"),
    ],
)
def test_two_times_said_as_a_span_are_the_start_and_the_end(
    light: ApplianceModel, sentence: str, start: str, end: str
) -> None:
    goal = parse_instruction(light, sentence)
    assert (goal.get("on_time"), goal.get("off_time")) == (start, end)
    assert "clock" not in goal


def _with_variable(model: str, name: str, spec: str, key: str) -> str:
    """The grow light with one more setting, entered by a key of its own then +/-."""
    control = f'  - {{id: {name}_button, kind: button, label: "{key}"}}\n'
    action = f"  press_{name}: {{control: {name}_button}}\n"
    steps = (
        f"  {name}:\n    - {{actions: [press_{name}]}}\n"
        + "    - actions: [press_up, press_down]\n"
        + f"      variable: {name}\n"
        + "      effect: {press_up: next, press_down: prev}\n"
    )
    return (
        model.replace("variables:\n", f"variables:\n  {name}:\n{spec}", 1)
        .replace("controls:\n", "controls:\n" + control, 1)
        .replace("actions:\n  press_set", "actions:\n" + action + "  press_set", 1)
        .replace("features:\n", "features:\n" + steps, 1)
    )


_DAY_TIME = (
    '    type: time\n    ranges: [["00:00:00", "23:30:00", 1800]]\n    initial: "06:00:00"\n'
    "    wrap: true\n"
)


def test_a_span_without_one_start_and_end_pair_sets_neither() -> None:
    # a second time of day named for a start (the mat's): which start "from 6 am" is, is unsaid
    two = loads_model(_with_variable(GROW_LIGHT, "mat_on", _DAY_TIME, "MAT ON"))
    goal = parse_instruction(two, "Keep the seedlings lit from 6 am until 8 pm.")
    assert not {"on_time", "off_time", "mat_on"} & set(goal)


def test_ten_at_night_is_a_time_of_day() -> None:
    mentions = find_mentions(tokenize("lights off at 10 at night"))
    assert [(m.kind, m.value) for m in mentions] == [("clock", 22 * 3600)]


@pytest.mark.parametrize(
    ("sentence", "level"),
    [("The light at 75 percent.", "75"), ("Dim it to 25 %.", "25"), ("Full light, 100%.", "100")],
)
def test_a_percentage_names_a_level_listed_without_its_sign(
    light: ApplianceModel, sentence: str, level: str
) -> None:
    assert parse_instruction(light, sentence).get("level") == level


def test_a_percentage_off_the_listed_levels_is_not_forced_onto_them(light: ApplianceModel) -> None:
    assert "level" not in parse_instruction(light, "Soak for 10 minutes, 60 % humidity.")


@pytest.mark.parametrize(
    ("sentence", "name", "value"),
    [
        ("Seedlings on the warmest setting.", "mat", 32),
        ("As cool as it will go for the cuttings.", "mat", 20),
        ("Soak them for as long as it allows.", "soak", 40),
        ("The shortest soak, then the light at 50 %.", "soak", 5),
    ],
)
def test_a_superlative_of_a_kind_names_the_one_setting_of_that_kind(
    light: ApplianceModel, sentence: str, name: str, value: int
) -> None:
    assert parse_instruction(light, sentence).get(name) == value


def test_as_long_as_a_while_of_the_user_is_no_limit(light: ApplianceModel) -> None:
    assert "soak" not in parse_instruction(light, "Keep the mat warm as long as I'm away.")


def test_a_superlative_of_a_kind_with_two_settings_of_it_names_neither() -> None:
    # a second duration (a mist time): "as long as it allows" could be either
    spec = "    type: numeric\n    unit: min\n    ranges: [[1, 15, 1]]\n    initial: 5\n"
    two = loads_model(_with_variable(GROW_LIGHT, "mist", spec, "MIST"))
    goal = parse_instruction(two, "Run it as long as it allows.")
    assert "soak" not in goal and "mist" not in goal
    # (one duration only: the same sentence names it)
    assert parse_instruction(loads_model(GROW_LIGHT), "Run it as long as it allows.") == {
        "soak": 40
    }


@pytest.mark.parametrize(
    ("sentence", "expected"),
    [
        ("Row 8 km at drag 5.", {"goal_kind": "distance", "goal": 8, "drag": 5}),
        ("Burn 300 kcal today.", {"goal_kind": "calories", "goal": 300}),
        ("A 45-minute row.", {"goal": 45}),
        ("Row for an hour on drag 3.", {"goal": 60, "drag": 3}),
    ],
)
def test_a_figure_takes_the_mode_its_kind_names(
    rower: ApplianceModel, sentence: str, expected: dict[str, object]
) -> None:
    assert parse_instruction(rower, sentence) == expected


def test_a_figure_of_another_kind_than_the_mode_said_is_not_forced(rower: ApplianceModel) -> None:
    goal = parse_instruction(rower, "Count the calories, and row 8 km.")
    assert goal.get("goal_kind") == "calories" and "goal" not in goal
