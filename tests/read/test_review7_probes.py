"""Misfires a fresh-eyes review found in round 7's goal and reader rules, each as a sentence or
a small manual of our own: a weather word is no setting's scale end, a denied superlative sets
nothing, a percentage is said of the level, a raised noun must be a quantity the manual gives."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read import read_manual
from apbot.read.goal import parse_instruction
from apbot.read.number_tokens import tokenize
from apbot.read.numbers import find_mentions

# a tea maker: one water temperature, a start key
TEA = """
appliance: {id: tea_1, category: kettle, name: "Brewa T2 tea maker", brand: B}
controls:
  - {id: heat_button, kind: button, label: "HEAT"}
  - {id: go_button, kind: button, label: "GO"}
variables:
  heat:
    type: numeric
    unit: "°C"
    ranges: [[60, 100, 10]]
    initial: 100
    wrap: true
    label: "HEAT"
  running:
    type: discrete
    values: ["off", "on"]
actions:
  press_heat: {control: heat_button}
  press_go: {control: go_button}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
  go:
    - {actions: [press_go], variable: running, effect: toggle}
display:
  idle: "{heat}"
  indicators: [running]
"""


@pytest.fixture(scope="module")
def tea() -> ApplianceModel:
    return loads_model(TEA)


@pytest.mark.parametrize(
    "sentence",
    [
        "Frostiest, coldest night so far - keep the trays snug.",
        "The shed is warmest at noon; light at 50 %.",
        "In the hottest week of July, lamps on at 6 am and off at 10 pm.",
    ],
)
def test_a_superlative_of_the_weather_is_no_setting_end(
    light: ApplianceModel, sentence: str
) -> None:
    assert "mat" not in parse_instruction(light, sentence)


@pytest.mark.parametrize(
    ("sentence", "name"),
    [
        ("Keep the trays as warm as you want them.", "mat"),
        ("It is as cold as it gets out there; soak 10 minutes.", "mat"),
        ("Light them as long as you can.", "soak"),
    ],
)
def test_as_x_as_the_user_likes_is_no_limit(
    light: ApplianceModel, sentence: str, name: str
) -> None:
    assert name not in parse_instruction(light, sentence)


@pytest.mark.parametrize(
    "sentence",
    [
        "On the chilliest, coldest day of winter, make me a pot of tea.",
        "Hottest summer on record; tea please.",
    ],
)
def test_a_superlative_of_the_day_is_no_temperature(tea: ApplianceModel, sentence: str) -> None:
    assert "heat" not in parse_instruction(tea, sentence)


@pytest.mark.parametrize(
    "sentence",
    ["White tea, but not the hottest water.", "Oolong - never the hottest, please."],
)
def test_a_denied_superlative_sets_nothing(tea: ApplianceModel, sentence: str) -> None:
    assert "heat" not in parse_instruction(tea, sentence)


def test_the_kind_superlative_with_its_own_word_still_counts(tea: ApplianceModel) -> None:
    assert parse_instruction(tea, "Black tea at the hottest setting.").get("heat") == 100


def test_the_percentage_said_of_the_level_wins_over_an_earlier_one(light: ApplianceModel) -> None:
    goal = parse_instruction(light, "My tablet is at 50 %, light at 75 %.")
    assert goal.get("level") == "75"


@pytest.mark.parametrize(
    "sentence", ["The reservoir is 50 % full.", "Humidity in the tent is 75 %, soak 10 minutes."]
)
def test_a_percentage_said_of_something_else_is_no_level(
    light: ApplianceModel, sentence: str
) -> None:
    assert "level" not in parse_instruction(light, sentence)


def test_a_bare_number_after_a_settings_name_is_its_value(rower: ApplianceModel) -> None:
    assert parse_instruction(rower, "An evening row, drag 7 at night.").get("drag") == 7


@pytest.mark.parametrize(("said", "hour"), [("at 12 at night", 0), ("by 1 at night", 1)])
def test_midnight_and_the_small_hours_at_night(said: str, hour: int) -> None:
    mentions = find_mentions(tokenize(f"lights off {said}"))
    assert [(m.kind, m.value) for m in mentions] == [("clock", hour * 3600)]


def _spa(arrows: str) -> str:
    """A foot spa manual of our own whose arrow pair's legend is ``arrows``."""
    return f"""# Foot spa

## The keys

| Key | What it does |
|---|---|
| ON/OFF | Switches the spa on or off. |
| ▲ / ▼ | {arrows} |
| TIMER | Shows and changes the switch-off time. |

## Switch-off time

Each press of TIMER moves to the next time in this order:
10 min > 20 min > 30 min > 45 min > 60 min > 10 min ...
"""


_SPA_KEYS = ["press_on_off", "press_up", "press_down", "press_timer"]


def _arrow_settings(manual: str) -> set[str]:
    model = read_manual(manual, _SPA_KEYS).model
    return {
        s.variable for steps in model.features.values() for s in steps if "press_up" in s.actions
    } - {None}  # type: ignore[misc]


@pytest.mark.parametrize(
    ("arrows", "not_named"),
    [
        ("Choose the jet power, 1 to 5. Press ▲ to raise the heel rest.", "heel"),
        ("Raise / lower the cover before filling; then choose the power from 1 to 5.", "cover"),
        ("Alter the figure. Kept pressed, they will lower the hum of the pump.", "hum"),
    ],
)
def test_a_raised_noun_the_manual_gives_no_amount_names_no_setting(
    arrows: str, not_named: str
) -> None:
    names = _arrow_settings(_spa(arrows))
    assert not any(not_named in n for n in names), names


def test_a_raised_noun_with_its_range_still_names_the_pair() -> None:
    names = _arrow_settings(_spa("Raise / lower the jet firmness, from 1 to 5."))
    assert any("firmness" in n for n in names), names


# a dehumidifier of our own: the arrows set the humidity; MODE chooses how it runs
_DRYER = """# Room dryer

## Keys

| Key | What it does |
|---|---|
| POWER | Switches the dryer on or off. |
| MODE | Changes between AUTO, CONTINUOUS and LAUNDRY. |
| ▲ / ▼ | {arrows} |
""".format(
    arrows="Set the target humidity from 35 to 75 %, in steps of 5 %. "
    "▲ and ▼ change nothing in the current mode when it is LAUNDRY."
)


def test_a_condition_on_the_current_mode_does_not_make_the_amount_per_mode() -> None:
    model = read_manual(_DRYER, ["press_power", "press_mode", "press_up", "press_down"]).model
    (var,) = {
        s.variable for steps in model.features.values() for s in steps if "press_up" in s.actions
    } - {None}
    assert model.variables[var].depends_on is None, model.variables[var]


def test_a_duration_that_says_when_is_not_the_goal_figure(rower: ApplianceModel) -> None:
    goal = parse_instruction(rower, "Within 20 minutes, I'd like to burn 250 kcal.")
    assert goal.get("goal") == 250 and goal.get("goal_kind") == "calories"


def test_two_figures_of_different_kinds_set_neither_and_km_is_no_drag(
    rower: ApplianceModel,
) -> None:
    goal = parse_instruction(rower, "Row for 10 minutes to loosen up, then 6 km.")
    assert "goal" not in goal and "drag" not in goal


def test_two_things_switched_on_and_off_are_no_span(light: ApplianceModel) -> None:
    goal = parse_instruction(light, "Switch the soak on at 8 am, and the clock off at 6 pm.")
    assert "on_time" not in goal and "off_time" not in goal


def test_one_thing_switched_on_and_off_is_a_span(light: ApplianceModel) -> None:
    goal = parse_instruction(light, "The lamp on at 7 am and the lamp off at 9 pm.")
    assert (goal.get("on_time"), goal.get("off_time")) == ("07:00:00", "21:00:00")


def test_a_superlative_of_the_day_sets_no_clock(light: ApplianceModel) -> None:
    assert "clock" not in parse_instruction(light, "Longest day of the summer; light at 75 %.")
