"""The offline goal parser on the example models: values, units, negation, start, errors."""

from __future__ import annotations

import contextlib
import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from apbot.cli import app
from apbot.examples import load_example
from apbot.model.schema import ApplianceModel
from apbot.read.goal import GoalParseError, parse_instruction

runner = CliRunner()


@pytest.fixture(scope="module")
def washer() -> ApplianceModel:
    return load_example("washing_machine")


@pytest.fixture(scope="module")
def oven() -> ApplianceModel:
    return load_example("toaster_oven_dial")


@pytest.fixture(scope="module")
def keypad() -> ApplianceModel:
    return load_example("microwave_keypad")


def test_value_names_numbers_and_start(washer: ApplianceModel) -> None:
    goal = parse_instruction(washer, "Cotton wash at sixty degrees with an extra rinse, start it")
    assert goal == {
        "programme": "cotton",
        "temperature": "60",
        "extra_rinse": "on",
        "running": "on",
    }


def test_negation_and_dont_start(washer: ApplianceModel) -> None:
    goal = parse_instruction(
        washer, "Wool at 30, no extra rinse, lock the controls; don't start it yet"
    )
    assert goal == {
        "programme": "wool",
        "temperature": "30",
        "extra_rinse": "off",
        "child_lock": "on",
        "running": "off",
    }


def test_relative_time_goes_to_the_finish_setting(washer: ApplianceModel) -> None:
    goal = parse_instruction(washer, "Synthetics, spin 800, have it finished in 9 hours")
    # finished 9 hours from now: the countdown has to be started
    assert goal == {"programme": "synthetics", "spin_speed": 800, "finish_in": 9, "running": "on"}
    goal = parse_instruction(washer, "Synthetics with a finish time of 9 hours")
    assert goal == {"programme": "synthetics", "finish_in": 9}


def test_nothing_is_invented(washer: ApplianceModel) -> None:
    assert parse_instruction(washer, "Wool please.") == {"programme": "wool"}
    assert parse_instruction(washer, "Thank you!") == {}


def test_power_on_only_when_asked(washer: ApplianceModel) -> None:
    assert parse_instruction(washer, "Turn the machine on and pick wool")["power"] == "on"
    assert "power" not in parse_instruction(washer, "Turn on the child lock")


def test_durations_in_words_and_fahrenheit(oven: ApplianceModel) -> None:
    goal = parse_instruction(oven, "Bake at 350°F for half an hour with the light on")
    assert goal == {"function": "bake", "temperature": 180, "timer": "00:30:00", "light": "on"}


def test_time_words_and_numbers_keep_their_variables(keypad: ApplianceModel) -> None:
    goal = parse_instruction(
        keypad, "Cook for two and a half minutes at power level 7 and set a 5-minute kitchen timer"
    )
    assert goal["cook_time"] == "00:02:30" and goal["power_level"] == 7
    assert goal["kitchen_timer"] == "00:05:00"
    assert parse_instruction(keypad, "Set the clock to 7:30 pm") == {"clock": "07:30:00"}


def test_lowest_and_highest(oven: ApplianceModel) -> None:
    assert parse_instruction(oven, "Bake at the lowest temperature")["temperature"] == 60
    assert parse_instruction(oven, "Bake at the highest temperature")["temperature"] == 230


def test_out_of_range_is_an_error_naming_the_words(washer: ApplianceModel) -> None:
    with pytest.raises(GoalParseError) as info:
        parse_instruction(washer, "Cotton with the spin at 5000 rpm")
    assert info.value.words == "5000 rpm"
    assert "spin_speed" in info.value.reason and "1400" in info.value.reason


def test_fahrenheit_far_from_every_celsius_value_is_an_error(oven: ApplianceModel) -> None:
    with pytest.raises(GoalParseError, match="temperature"):
        parse_instruction(oven, "Bake at 600 °F")


@settings(deadline=None)
@given(st.text(max_size=120))
def test_random_text_never_raises_anything_else(text: str) -> None:
    model = load_example("washing_machine")
    try:
        goal = parse_instruction(model, text)
    except GoalParseError:
        return
    assert set(goal) <= set(model.variables)


WORDS = st.sampled_from(
    [
        "set",
        "start",
        "don't",
        "no",
        "the",
        "a",
        "at",
        "for",
        "in",
        "to",
        "and",
        "half",
        "an",
        "hour",
        "minutes",
        "2",
        "hrs",
        "7:30",
        "pm",
        "60",
        "degrees",
        "°F",
        "%",
        "wool",
        "cotton",
        "spin",
        "rinse",
        "lock",
        "on",
        "off",
        "finish",
        "ready",
        "1400",
        "rpm",
        "twenty-five",
        "lowest",
    ]
)


@settings(deadline=None)
@given(st.lists(WORDS, max_size=25).map(" ".join))
def test_random_appliance_words_never_raise_anything_else(text: str) -> None:
    for name in ("washing_machine", "toaster_oven_dial", "microwave_keypad"):
        model = load_example(name)
        with contextlib.suppress(GoalParseError):
            parse_instruction(model, text)


def test_cli_goal_prints_json() -> None:
    result = runner.invoke(app, ["goal", "washing_machine", "Wool at 30 degrees", "--json"])
    assert result.exit_code == 0, result.output
    assert json.loads(result.output) == {"programme": "wool", "temperature": "30"}


def test_cli_goal_error_exits_1() -> None:
    result = runner.invoke(app, ["goal", "washing_machine", "Spin at 5000 rpm"])
    assert result.exit_code == 1
    assert "5000 rpm" in result.output and "Traceback" not in result.output


def test_cli_eval_goals_on_a_subset() -> None:
    result = runner.invoke(
        app, ["eval-goals", "--categories", "kettle", "--appliances", "kettle_1", "--json"]
    )
    assert result.exit_code == 0, result.output
    scores = json.loads(result.output)
    assert scores["overall"]["n"] == 10
    assert set(scores["categories"]) == {"kettle"}
    assert 0.0 <= scores["overall"]["accuracy"] <= 1.0
    right = round(scores["overall"]["accuracy"] * 10)
    assert len(scores["misses"]) == 10 - right


def test_cli_eval_goals_with_nothing_chosen() -> None:
    result = runner.invoke(app, ["eval-goals", "--categories", "toaster"])
    assert result.exit_code == 1
    assert "no tasks" in result.output


def test_a_setting_the_programme_lacks_is_an_error() -> None:
    from apbot.bench.suite import bundled_suite_dir, load_appliance

    model = load_appliance(bundled_suite_dir() / "bread_maker_2").model
    with pytest.raises(GoalParseError, match="does not apply when menu is 'dough'"):
        parse_instruction(model, "Dough programme, 2 lb, start right away")


def test_denied_verb_and_celsius_on_a_fahrenheit_dial() -> None:
    from apbot.bench.suite import bundled_suite_dir, load_appliance

    kettle = load_appliance(bundled_suite_dir() / "kettle_1").model
    assert parse_instruction(kettle, "I need 95°C water, don't heat it yet") == {
        "temperature": 95,
        "heating": "off",
    }
    fryer = load_appliance(bundled_suite_dir() / "air_fryer_1").model
    goal = parse_instruction(fryer, "Bake at 180 °C for 25 minutes")
    assert goal["temperature"] == 350  # 356 °F, the dial's nearest mark


def test_percent_power_clock_needs_naming_and_switch_words() -> None:
    from apbot.bench.suite import bundled_suite_dir, load_appliance

    microwave = load_appliance(bundled_suite_dir() / "microwave_1").model
    assert parse_instruction(microwave, "Microwave at 50% power for 2 min") == {
        "power_level": 5,
        "cook_time": "00:02:00",
        "running": "on",
    }
    bread = load_appliance(bundled_suite_dir() / "bread_maker_3").model
    assert parse_instruction(bread, "Jam cycle please and switch the light on") == {
        "cycle": "jam",
        "light": "on",
    }
    assert parse_instruction(bread, "French loaf with a light crust")["crust"] == "light"
    with pytest.raises(GoalParseError, match="ready_at"):
        parse_instruction(bread, "Brioche done at 8:15 tomorrow")  # the timer has 10-minute steps


def test_cli_run_reads_the_goal_of_any_instruction() -> None:
    text = "Heat the water to 70 degrees and keep it warm"
    result = runner.invoke(app, ["run", "kettle_1", text, "--belief", "true"])
    assert result.exit_code == 0, result.output
    assert "temperature=70" in result.output and "keep_warm=on" in result.output
    # --parse-goal, once needed, is the default now and still accepted
    again = runner.invoke(app, ["run", "kettle_1", text, "--belief", "true", "--parse-goal"])
    assert again.exit_code == 0 and "temperature=70" in again.output


def test_an_overlong_instruction_is_refused(washer: ApplianceModel) -> None:
    with pytest.raises(GoalParseError, match="at most 5,000"):
        parse_instruction(washer, "wool " * 2000)


def _suite_models() -> list[ApplianceModel]:
    from apbot.bench.suite import load_suite

    return [appliance.model for appliance in load_suite("bundled").appliances]


SUITE_MODELS = _suite_models()


@settings(deadline=None, max_examples=60)
@given(
    st.sampled_from(range(len(SUITE_MODELS))),
    st.lists(
        st.one_of(
            WORDS,
            st.sampled_from(["start", "lock", "no", "lowest", "full", "at", "for", "ready by"]),
            st.integers(0, 3000).map(str),
        ),
        max_size=20,
    ).map(" ".join),
)
def test_every_bundled_model_reads_random_instructions(index: int, text: str) -> None:
    model = SUITE_MODELS[index]
    try:
        goal = parse_instruction(model, text)
    except GoalParseError:
        return
    from apbot.model.goal import parse_goal

    assert parse_goal(model, goal) == goal  # every value is canonical and in its domain


def test_an_unknown_programme_name_is_an_error(washer: ApplianceModel) -> None:
    with pytest.raises(GoalParseError) as info:
        parse_instruction(washer, "Run the turbo programme at 40")
    assert info.value.words == "turbo programme"
    assert "programme has no 'turbo'" in info.value.reason and "wool" in info.value.reason
    with pytest.raises(GoalParseError, match="programme has no 'silk'"):
        parse_instruction(washer, "Run the silk cycle")
    assert parse_instruction(washer, "Run the synthetic cycle")["programme"] == "synthetics"
    assert parse_instruction(washer, "Run the usual programme") == {"running": "on"}


def test_unlock_turns_the_lock_off(washer: ApplianceModel) -> None:
    assert parse_instruction(washer, "Unlock the keys")["child_lock"] == "off"
    assert parse_instruction(washer, "Lock the keys")["child_lock"] == "on"


def test_a_coded_value_by_its_number() -> None:
    from apbot.bench.suite import bundled_suite_dir, load_appliance

    model = load_appliance(bundled_suite_dir() / "microwave_3").model
    goal = parse_instruction(model, "Cook 800 g of chicken with auto menu 6 and start")
    assert goal == {"auto_menu": "A-6", "auto_weight": 800, "running": "on"}


def test_a_first_word_names_a_value_only_beside_the_settings_word() -> None:
    from apbot.bench.suite import bundled_suite_dir, load_appliance

    washer = load_appliance(bundled_suite_dir() / "washing_machine_1").model
    assert parse_instruction(washer, "Run the eco programme")["programme"] == "eco 40-60"
    hob = load_appliance(bundled_suite_dir() / "induction_cooker_1").model
    assert "function" not in parse_instruction(hob, "keep it hot for an hour")  # not HOT POT


def test_quantity_values_by_quantity(keypad: ApplianceModel) -> None:
    goal = parse_instruction(keypad, "Pop a 3.0 oz bag of popcorn and start")
    assert goal == {"popcorn_size": "3.0 oz", "running": "on"}
    assert parse_instruction(keypad, "Popcorn, the 1.75 ounce bag")["popcorn_size"] == "1.75 oz"


def test_counts_and_and_in_value_names(oven: ApplianceModel, washer: ApplianceModel) -> None:
    assert parse_instruction(oven, "Toast two slices at shade 3") == {
        "function": "toast",
        "toast_shade": 3,
    }
    goal = parse_instruction(washer, "Rinse and spin at 600 rpm")
    assert goal == {"programme": "rinse and spin", "spin_speed": 600}


def test_a_time_of_day_for_a_delay_is_an_error(washer: ApplianceModel) -> None:
    with pytest.raises(GoalParseError, match="finish_in is a time from now"):
        parse_instruction(washer, "Wool at 30 degrees and finish by 7 am")


def test_start_in_a_settings_name_is_not_a_start() -> None:
    from apbot.bench.suite import bundled_suite_dir, load_appliance

    model = load_appliance(bundled_suite_dir() / "washing_machine_3").model
    goal = parse_instruction(model, "Cottons at 40, set the delay start to 3 hours")
    assert goal == {"programme": "cottons", "delay_start": "03:00:00", "temperature": "40"}
    assert parse_instruction(model, "Cottons, delay 3 hours and start it")["running"] == "on"
