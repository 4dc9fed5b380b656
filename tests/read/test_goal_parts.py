"""The goal parser's newer rules: twins, coded values named by the manual, on/off timers, the
start convention, and what is not a start."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from apbot.bench.runner import cached_suite
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction
from apbot.read.goal_manual import coded_names
from apbot.read.goal_twins import find_twins
from apbot.read.goal_vocab import split_camel


def _goal(appliance_id: str, text: str) -> dict[str, object]:
    appliance = cached_suite("bundled").get(appliance_id)
    return parse_instruction(appliance.model, text, appliance.manual)


def test_twin_settings_take_the_value_of_the_zone_named() -> None:
    groups = find_twins(cached_suite("bundled").get("induction_cooker_5").model)
    assert {g.names for g in groups} == {
        ("front_level", "rear_level"),
        ("front_timer", "rear_timer"),
    }
    assert _goal(
        "slow_cooker_2", "Both sides at 900 watts, and the left side should turn off after an hour."
    ) == {"left_power": 900, "right_power": 900, "left_timer": "01:00:00"}
    goal = _goal("air_fryer_4", "Zone 1 at 160 degrees for a quarter of an hour, zone 2 at 190")
    assert goal["temp1"] == 160 and goal["time1"] == "00:15:00" and goal["temp2"] == 190


def test_coded_values_are_named_by_the_manual_table() -> None:
    appliance = cached_suite("bundled").get("dehumidifier_3")
    assert ("humidistat", "2", "60 %") in coded_names(appliance.model, appliance.manual)
    assert _goal("dehumidifier_3", "Keep the room at about 60% humidity") == {"humidistat": "2"}
    assert _goal("bread_maker_1", "A whole wheat loaf, 1 kg")["menu"] == "3"
    # without the manual the code cannot be known, and the parser says nothing of it
    model = cached_suite("bundled").get("bread_maker_1").model
    assert "menu" not in parse_instruction(model, "A sandwich loaf, 1 kg")


@pytest.mark.parametrize(
    ("text", "timer"),
    [
        ("Cool to 22 degrees and switch off after 2 hours", "timer_off"),
        ("An off-timer of 3 hours, please", "timer_off"),
        ("Have it come on in 7.5 hours", "timer_on"),
    ],
)
def test_on_and_off_timers_are_told_apart(text: str, timer: str) -> None:
    assert timer in _goal("air_conditioner_1", text)


def test_starts_said_of_others_or_later_are_not_requests() -> None:
    assert _goal(
        "coffee_machine_2", "Choose a lungo and lock the keys so the kids can't start it"
    ) == {
        "drink": "lungo",
        "key_lock": "on",
    }
    assert "running" not in _goal("blender_2", "Set speed 4; I'll start it myself.")
    assert _goal("blender_1", "Blend the sauce at speed 5.") == {"speed": 5, "running": "on"}


def test_a_power_only_appliance_is_switched_on_by_start() -> None:
    assert _goal("air_conditioner_2", "Cool at 24 degrees and start it.")["power"] == "on"
    assert "power" not in _goal(
        "dehumidifier_4", "Have the dehumidifier start by itself in six hours."
    )


def test_run_together_names_and_short_forms() -> None:
    assert split_camel("ExtraDry") == "Extra Dry"
    goal = _goal("dishwasher_2", "Eco 50 with varioSpeed and ExtraDry")
    assert goal["vario_speed"] == "on" and goal["extra_dry"] == "on"
    assert _goal("dishwasher_3", "Eco with tablets")["tabs"] == "on"


@settings(max_examples=60, deadline=None)
@given(
    st.text(alphabet=st.sampled_from(list("| -*:1234PA\nabc LIGHTonf.%")), max_size=300),
    st.text(max_size=80),
)
def test_any_manual_and_sentence_give_a_goal_or_a_clear_error(manual: str, text: str) -> None:
    from apbot.read.goal import GoalParseError

    model = cached_suite("bundled").get("bread_maker_1").model
    try:
        goal = parse_instruction(model, text, manual)
    except GoalParseError as exc:
        assert exc.words is not None and exc.reason
    else:
        assert set(goal) <= set(model.variables)


def _menu_model(values: list[str]) -> ApplianceModel:
    return ApplianceModel.model_validate(
        {
            "appliance": {"id": "m", "category": "bread_maker", "name": "m"},
            "variables": {"menu": {"type": "discrete", "values": values}},
            "controls": [{"id": "menu", "kind": "button", "label": "MENU"}],
            "actions": {"press_menu": {"control": "menu"}},
            "features": {
                "menu": [{"actions": ["press_menu"], "variable": "menu", "effect": "next"}]
            },
        }
    )


def test_tables_drawn_with_spaces_name_coded_values() -> None:
    # a converted PDF draws its tables with spaces; a parts legend drawn the same way names
    # nothing (it covers too few of the codes, and a better table exists)
    manual = (
        "PARTS\n\n  1   Lid with window        4   Pan\n  2   Handle             5   Blade\n"
        "\nPROGRAMMES\n\n No.  Programme      Use                 Time\n"
        " 1    Plain          White loaves        3:00\n"
        " 2    Rye            Rye flour mixes     3:30\n"
        " 3    Brioche        Rich, sweet dough   3:10\n"
        " 4    Dough only     No baking           1:30\n"
        " 5    Jam            Fruit and sugar     1:05\n"
        " 6    Bake           Baking only         1:00\n"
    )
    names = coded_names(_menu_model([str(n) for n in range(1, 7)]), manual)
    assert ("menu", "3", "Brioche") in names and ("menu", "4", "Dough only") in names
    assert not any(label.startswith(("Lid", "Handle", "Pan")) for _, _, label in names)
    # a row of marks above a row of what each means
    dial = (
        "Turn the dial to a mark:\n\n"
        "     Mark        1       2       3       MAX\n"
        "     Output      low     medium  high    full power\n"
    )
    names = coded_names(_menu_model(["1", "2", "3", "max"]), dial)
    assert ("menu", "2", "medium") in names and ("menu", "max", "full power") in names


def test_a_titles_and_joins_words_of_one_name_and_only_the_title_names_the_appliance() -> None:
    from apbot.read.goal_manual import title_nouns

    none: frozenset[str] = frozenset()
    assert title_nouns("# Soy & Nut Milk Maker\n\nThank you.\n", none) == {"maker"}
    assert title_nouns("# Yogurt and Cheese Maker\n", frozenset({"yogurt"})) == {"maker"}
    assert title_nouns("# Juice and Smoothie Maker\n", none) == {"maker"}
    assert title_nouns("# Mira Soup Urn & Warmer\n", none) == {"urn"}  # an urn that also warms
    assert title_nouns("# Mira Soup Urn with Tap and Light\n", none) == {"urn"}
    parts = "# Mira MX-7\n\n## Parts\n\n### Inner pot\n"
    assert title_nouns(parts, none) == set()  # a part named in a section is no appliance
    poster = "# Mira MX-7 Owner's Manual\n\n## Wall sticker\n"
    assert title_nouns(poster, none) == set()  # a section's "-er" word is no appliance
    safety = "# Important Safety Instructions\n\nRead them.\n\n# Mira Soup Urn\n\n## Parts\n"
    assert title_nouns(safety, none) == {"urn"}
