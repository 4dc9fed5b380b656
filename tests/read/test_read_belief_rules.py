"""Rules for what a model read from a manual gets wrong in ways the goal parser and the
reader can still bear: a unitless setting, a numbered menu read as a number, a range written
in two units."""

from __future__ import annotations

from typing import Any

from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction
from apbot.read.values import Range, find_ranges


def _model(variables: dict[str, Any], labels: dict[str, str] | None = None) -> ApplianceModel:
    labels = labels or {}
    actions = {f"press_{name}": {"control": name} for name in variables}
    return ApplianceModel.model_validate(
        {
            "appliance": {"id": "m", "category": "test", "name": "m"},
            "variables": variables,
            "controls": [
                {"id": n, "kind": "button", "label": labels.get(n, n.upper())} for n in variables
            ],
            "actions": actions,
            "features": {
                f"set_{n}": [{"actions": [f"press_{n}"], "variable": n, "effect": "next"}]
                for n in variables
            },
        }
    )


def test_a_range_written_in_two_time_units_is_read_in_the_smaller() -> None:
    assert find_ranges("| Timer | 1 min – 3 h |") == [Range(1, 180, "min")]
    assert find_ranges("from 30 s to 90 min") == [Range(30, 5400, "s")]
    assert find_ranges("1–60 min") == [Range(1, 60, "min")]


def test_a_unit_the_reader_missed_is_still_the_settings_kind() -> None:
    spin = {"type": "numeric", "ranges": [[0, 1400, 200]], "label": "SPIN"}
    model = _model({"spin": spin})
    assert parse_instruction(model, "a wash with a 1000 rpm spin") == {"spin": 1000}
    temp = {"type": "numeric", "ranges": [[20, 90, 10]], "label": "TEMP"}
    assert parse_instruction(_model({"temp": temp}), "wash it at 60 degrees") == {"temp": 60}


def test_a_numbered_menu_read_as_a_number_is_named_by_the_manuals_table() -> None:
    menu = {"type": "numeric", "ranges": [[1, 15, 1]], "label": "MENU"}
    manual = (
        "| No. | Menu | No. | Menu | No. | Menu |\n|---|---|---|---|---|---|\n"
        "| 1 | Basic | 6 | Rapid | 11 | Jam |\n| 2 | French | 7 | Express | 12 | Yogurt |\n"
        "| 5 | Gluten-free | 10 | Cake | 15 | Bake |\n"
    )
    model = _model({"menu": menu})
    assert parse_instruction(model, "the gluten-free menu, please", manual) == {"menu": 5}
    assert parse_instruction(model, "make some jam", manual) == {"menu": 11}
    # a setting with a unit counts something: its numbers are no codes
    weight = {"type": "numeric", "ranges": [[1, 15, 1]], "label": "WEIGHT", "unit": "kg"}
    assert "weight" not in parse_instruction(_model({"weight": weight}), "the jam one", manual)


def test_the_end_of_a_hyphenated_compound_is_a_weaker_name_than_a_whole_word() -> None:
    cycle = {"type": "discrete", "values": ["auto", "steril", "dry", "keep"], "label": "CYCLE"}
    model = _model({"cycle": cycle})
    said = "Only sterilise them this time, I will air-dry them myself."
    assert parse_instruction(model, said) == {"cycle": "steril"}
    assert parse_instruction(model, "the automatic steam-and-dry cycle") == {"cycle": "auto"}
    assert parse_instruction(model, "just dry them") == {"cycle": "dry"}


def test_a_settings_name_beside_a_synonym_of_its_value_is_that_setting() -> None:
    # a reader may file a setting's own name among another setting's values
    rice = {"type": "discrete", "values": ["white", "brown"], "label": "RICE"}
    extra = {"type": "discrete", "values": ["texture", "if needed"], "label": "MENU"}
    texture = {"type": "discrete", "values": ["regular", "softer", "harder"], "label": "TEXTURE"}
    model = _model({"rice": rice, "extra": extra, "texture": texture})
    assert parse_instruction(model, "cook the brown rice on a soft texture") == {
        "rice": "brown",
        "texture": "softer",
    }
    assert parse_instruction(model, "white rice; I like the texture firm") == {
        "rice": "white",
        "texture": "harder",
    }


def test_a_switch_named_like_a_setting_that_took_a_value_is_not_named_again() -> None:
    # a reader may keep a key's hold function as a switch under the same label
    cook = {"type": "time", "ranges": [["00:30:00", "04:00:00", 600]], "label": "COOK TIME"}
    hold = {"type": "discrete", "values": ["off", "on"], "label": "COOK TIME"}
    model = _model({"cook_time": cook, "cook_time_hold": hold})
    assert parse_instruction(model, "I need a cook time of 90 minutes") == {"cook_time": "01:30:00"}


def test_the_manuals_title_names_the_appliance_a_reader_left_unnamed() -> None:
    power = {"type": "discrete", "values": ["off", "on"], "label": "POWER"}
    temp = {"type": "numeric", "ranges": [[40, 95, 5]], "unit": "°C", "label": "TEMP"}
    model = _model({"power": power, "temp": temp})
    said = "Turn on the urn, then 85 degrees please."
    assert parse_instruction(model, said) == {"temp": 85}  # the belief says nothing of an urn
    titled = "# Calda C-2 Hot Drinks Urn\n\nThank you for choosing Calda.\n"
    assert parse_instruction(model, said, titled) == {"power": "on", "temp": 85}
    plain = "CALDA\nBeverage equipment\nC-2 test Urn 2.5 kW\nInstruction manual\n"
    assert parse_instruction(model, said, plain) == {"power": "on", "temp": 85}
    assert parse_instruction(model, "Turn the temp on", titled) == {}


def test_the_titles_head_noun_comes_before_its_extras_and_a_safety_heading_names_nothing() -> None:
    power = {"type": "discrete", "values": ["off", "on"], "label": "POWER"}
    temp = {"type": "numeric", "ranges": [[60, 220, 10]], "unit": "°C", "label": "TEMP"}
    model = _model({"power": power, "temp": temp})
    extras = "# Countertop Soup Urn with Viewing Window and Light\n\nThank you.\n"
    assert parse_instruction(model, "Turn the light on, 150 degrees", extras) == {"temp": 150}
    on = {"power": "on", "temp": 150}
    assert parse_instruction(model, "Turn on the urn, 150 degrees", extras) == on
    safety = "# Important Safety Instructions\n\nRead them.\n\n# Kora SU-2 Soup Urn\n"
    assert parse_instruction(model, "Turn the urn on at 150 degrees", safety) == on
    brand = "# Kora SU-2 — Soup Urn & Warmer\n"  # the part after the brand; not the "& Warmer"
    assert parse_instruction(model, "Turn the urn on at 150 degrees", brand) == on
    assert parse_instruction(model, "Turn the warmer on at 150 degrees", brand) == {"temp": 150}


def test_output_is_a_word_for_power() -> None:
    watt = {"type": "numeric", "ranges": [[500, 3500, 100]], "label": "WATT"}
    time = {"type": "numeric", "ranges": [[1, 180, 1]], "label": "TIME", "unit": "min"}
    model = _model({"watt": watt, "time": time})
    assert parse_instruction(model, "use the smallest output for a quarter of an hour") == {
        "watt": 500,
        "time": 15,
    }


def test_a_timer_that_wraps_round_the_day_beside_a_clock_is_when_it_is_done() -> None:
    day = {
        "type": "time",
        "wrap": True,
        "format": "hh:mm",
        "ranges": [["00:00:00", "23:59:00", 60]],
    }
    menu = {"type": "discrete", "values": ["white", "brown", "porridge"], "label": "MENU"}
    model = _model(
        {"clock": {**day, "label": "CLOCK"}, "timer": {**day, "label": "TIMER"}, "menu": menu}
    )
    said = "Make porridge and have it done at 6:45 in the morning."
    assert parse_instruction(model, said) == {"menu": "porridge", "timer": "06:45:00"}
    said = "Set the clock to 13:05, then brown rice ready at half past six."
    assert parse_instruction(model, said) == {
        "clock": "13:05:00",
        "menu": "brown",
        "timer": "06:30:00",
    }


def test_a_legends_words_in_an_instruction_do_not_set_that_key() -> None:
    # a legend says what a key is for; the same words in an instruction describe the load
    # or the user's wish, not that key (a rule that matched them set these switches)
    prewash = {"type": "discrete", "values": ["off", "on"], "label": "PREWASH"}
    programme = {"type": "discrete", "values": ["cottons", "synthetics"], "label": "PROGRAMME"}
    temp = {"type": "numeric", "ranges": [[20, 90, 10]], "label": "TEMP", "unit": "C"}
    washer = _model({"prewash": prewash, "programme": programme, "temp": temp})
    legend = "PREWASH — an extra wash first, for laundry that is heavily soiled.\n"
    said = "Cottons at 60 degrees, the laundry is heavily soiled."
    assert parse_instruction(washer, said, legend) == {"programme": "cottons", "temp": 60}
    lock = {"type": "discrete", "values": ["off", "on"], "label": "CHILD LOCK"}
    heat = {"type": "numeric", "ranges": [[100, 250, 10]], "label": "TEMP", "unit": "C"}
    oven = _model({"lock": lock, "heat": heat}, labels={"lock": "STOP/CANCEL"})
    legend = "STOP/CANCEL     Halts the oven and wipes out the settings you keyed in.\n"
    said = "Wipe out the settings I keyed in and heat the oven to 200 degrees."
    assert parse_instruction(oven, said, legend) == {"heat": 200}
