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
from apbot.read.numbers import find_mentions, tokenize

GROW_LIGHT = """
appliance: {id: grow_1, category: grow_light, name: "Sprout S1 seedling light", brand: S}
controls:
  - {id: set_button, kind: button, label: "SET"}
  - {id: on_button, kind: button, label: "ON TIME"}
  - {id: off_button, kind: button, label: "OFF TIME"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
  - {id: level_button, kind: button, label: "LEVEL"}
  - {id: mat_button, kind: button, label: "MAT"}
  - {id: soak_button, kind: button, label: "SOAK"}
variables:
  clock:
    type: time
    ranges: [["00:00:00", "23:59:00", 60]]
    initial: "12:00:00"
    wrap: true
    label: "CLOCK"
  on_time:
    type: time
    ranges: [["00:00:00", "23:30:00", 1800]]
    initial: "07:00:00"
    wrap: true
    label: "ON TIME"
  off_time:
    type: time
    ranges: [["00:00:00", "23:30:00", 1800]]
    initial: "19:00:00"
    wrap: true
    label: "OFF TIME"
  level:
    type: discrete
    values: ["25", "50", "75", "100"]
    show: {"25": "▮▯▯▯", "50": "▮▮▯▯", "75": "▮▮▮▯", "100": "▮▮▮▮"}
  mat:
    type: numeric
    unit: "°C"
    ranges: [[20, 32, 1]]
    initial: 24
    label: "MAT"
  soak:
    type: numeric
    unit: min
    ranges: [[5, 40, 5]]
    initial: 10
    label: "SOAK"
actions:
  press_set: {control: set_button}
  press_on: {control: on_button}
  press_off: {control: off_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_level: {control: level_button}
  press_mat: {control: mat_button}
  press_soak: {control: soak_button}
features:
  clock:
    - {actions: [press_set]}
    - actions: [press_up, press_down]
      variable: clock
      effect: {press_up: next, press_down: prev}
  on_time:
    - {actions: [press_on]}
    - actions: [press_up, press_down]
      variable: on_time
      effect: {press_up: next, press_down: prev}
  off_time:
    - {actions: [press_off]}
    - actions: [press_up, press_down]
      variable: off_time
      effect: {press_up: next, press_down: prev}
  level:
    - {actions: [press_level], variable: level, effect: next}
  mat:
    - {actions: [press_mat]}
    - actions: [press_up, press_down]
      variable: mat
      effect: {press_up: next, press_down: prev}
  soak:
    - {actions: [press_soak]}
    - actions: [press_up, press_down]
      variable: soak
      effect: {press_up: next, press_down: prev}
display:
  idle: "{clock}"
  indicators: [level]
"""

ROWER = """
appliance: {id: rower_1, category: rowing_machine, name: "Glide R3 rowing machine", brand: G}
controls:
  - {id: goal_button, kind: button, label: "GOAL"}
  - {id: up_button, kind: button, label: "▲"}
  - {id: down_button, kind: button, label: "▼"}
  - {id: drag_button, kind: button, label: "DRAG"}
variables:
  goal_kind:
    type: discrete
    values: [time, distance, calories]
    show: {time: "TIME", distance: "DIST", calories: "ENERGY"}
  goal:
    type: numeric
    depends_on: goal_kind
    cases:
      time: {ranges: [[5, 90, 5]], initial: 20}
      distance: {ranges: [[1, 30, 1]], initial: 2}
      calories: {ranges: [[50, 1500, 50]], initial: 200}
    show: "{value}"
  drag:
    type: numeric
    ranges: [[1, 8, 1]]
    initial: 4
    wrap: true
    label: "DRAG"
actions:
  press_goal: {control: goal_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_drag: {control: drag_button}
features:
  goal_kind:
    - {actions: [press_goal], variable: goal_kind, effect: next}
  goal:
    - actions: [press_up, press_down]
      variable: goal
      effect: {press_up: next, press_down: prev}
  drag:
    - {actions: [press_drag], variable: drag, effect: next}
display:
  idle: "{goal}"
  indicators: [goal_kind]
"""


@pytest.fixture(scope="module")
def light() -> ApplianceModel:
    return loads_model(GROW_LIGHT)


@pytest.fixture(scope="module")
def rower() -> ApplianceModel:
    return loads_model(ROWER)


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
