"""Rules from probing the reader with short manuals of our own (probe16): each rule on a small
manual written in different words from the probe that found it."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual
from apbot.read.table_transposed import key_row_marks, sideways_choices
from apbot.read.text import parse_manual
from apbot.read.value_lists import find_list


def _values(text: str, actions: list[str], variable: str) -> list[str] | None:
    """The values read for one variable (None for a number or a time)."""
    model: dict[str, Any] = read_manual(text, actions).model.model_dump(mode="json")
    return model["variables"][variable].get("values")


# a kiln whose firing schedules are the table's COLUMNS: one row per quantity, each in its unit
KILN = """# Brennwerk K-9 Hobby Kiln

## Controls

| Control | Function |
|---|---|
| **MAINS** | Switches the kiln on and off. |
| **SCHEDULE** | Picks the firing schedule. |
| **FIRE** | Begins firing. |

## Firing schedules

What each schedule does:

| Schedule | Bisque | Glaze | Lustre | Decal |
|---|---|---|---|---|
| Top temperature | 1000 °C | 1220 °C | 750 °C | 800 °C |
| Soak | 10 min | 15 min | 5 min | 5 min |
| Vent open | yes | – | yes | yes |

Press **SCHEDULE** until the one you want is lit.
"""

KILN_KEYS = ["press_mains", "press_schedule", "press_fire"]


def test_a_table_written_sideways_gives_its_header_cells_as_the_keys_values() -> None:
    assert _values(KILN, KILN_KEYS, "schedule") == ["bisque", "glaze", "lustre", "decal"]


def test_a_choice_key_takes_the_columns_of_a_sideways_table_headed_by_a_programme_noun() -> None:
    text = KILN.replace("SCHEDULE", "MODE").replace("| Schedule |", "| Programme |")
    assert _values(text, ["press_mains", "press_mode", "press_fire"], "mode") == [
        "bisque",
        "glaze",
        "lustre",
        "decal",
    ]


def test_a_table_written_the_usual_way_is_not_read_sideways() -> None:
    usual = """| Schedule | Top temperature | Soak |
|---|---|---|
| Bisque | 1000 °C | 10 min |
| Glaze | 1220 °C | 15 min |
| Lustre | 750 °C | 5 min |
"""
    units = parse_manual(usual, []).units
    head = next(i for i, u in enumerate(units) if u.cells and not u.header)
    assert sideways_choices(units, head) is None
    sideways = KILN[KILN.index("| Schedule") : KILN.index("Press **SCHEDULE**")]
    units = parse_manual(sideways, []).units
    head = next(i for i, u in enumerate(units) if u.cells and not u.header)
    assert sideways_choices(units, head) == ["Bisque", "Glaze", "Lustre", "Decal"]


# a humidifier whose key chooses between two capitalised names in running prose
HUMIDIFIER = """# Nebula H-2 Humidifier

## Controls

| Control | Function |
|---|---|
| **ON/OFF** | Switches the humidifier on and off. |
| **OUTPUT** | Sets the mist output. |

## Mist output

Press **OUTPUT** to select Quiet or Boost (Quiet is used after switching on).
"""


def test_two_capitalised_names_after_a_cue_are_the_keys_two_values() -> None:
    values = _values(HUMIDIFIER, ["press_on_off", "press_output"], "output")
    assert values == ["quiet", "boost"]


def test_a_capitalised_pair_is_a_list_but_plain_words_are_not() -> None:
    assert find_list("For the towels you can choose Dry or Damp.") == (["Dry", "Damp"], "list")
    assert find_list("To finish, choose between Light Wash and Heavy Wash.") == (
        ["Light Wash", "Heavy Wash"],
        "list",
    )
    assert find_list("For the towels you can choose dry or damp.") is None


# a grinder whose coarseness marks are printed in capitals across one table row, a single row
# of amounts under them (too few rows to tell the table's axes apart by units)
GRINDER = """# Mahlwerk G-5 Coffee Grinder

## Controls

| Control | Function |
|---|---|
| **ON/OFF** | Switches the grinder on and off. |
| **GRIND** | Sets how fine the coffee is ground. |

## Grind

| Grind | ESPRESSO | FILTER | PRESS | COLD BREW |
|---|---|---|---|---|
| Particle size | 0.3 mm | 0.6 mm | 1.0 mm | 1.4 mm |
"""


def test_capital_choices_over_a_single_row_of_amounts_are_the_keys_values() -> None:
    assert _values(GRINDER, ["press_on_off", "press_grind"], "grind") == [
        "espresso",
        "filter",
        "press",
        "cold brew",
    ]


def test_capital_choices_over_rows_of_names_only_are_a_table_of_columns() -> None:
    keys_over_lamps = """| TEMP. | SPIN | SOIL |
|---|---|---|
| Hot | High | Heavy |
| Cold | Low | Light |
"""
    units = parse_manual(keys_over_lamps, []).units
    head = next(i for i, u in enumerate(units) if u.cells and not u.header)
    assert sideways_choices(units, head) is None


# a fryer whose browning marks are printed across the key's own row under a row of counts
FRYER = """# Croustil F-8 Air Fryer

## Controls

| Control | Function |
|---|---|
| **ON/OFF** | Switches the fryer on and off. |
| **CRISP** | Sets how crisp the food turns out. |

## Crispness

|   | 1 | 2 | 3 | 4 |
|---|---|---|---|---|
| **CRISP** | SOFT | EVEN | CRUNCHY | EXTRA |
"""


def test_a_keys_row_of_capital_marks_under_counts_gives_its_values() -> None:
    assert _values(FRYER, ["press_on_off", "press_crisp"], "crisp") == [
        "soft",
        "even",
        "crunchy",
        "extra",
    ]


def test_a_record_row_under_named_columns_is_no_row_of_marks() -> None:
    assert key_row_marks(("CRISP", "READY", "CRISP"), {"crisp"}, ("Key", "Shown", "Next")) is None
    assert key_row_marks(("Crisp", "SOFT", "EVEN"), {"crisp"}, ("", "1", "2")) == ["SOFT", "EVEN"]


def _sideways(table: str) -> list[str] | None:
    """What sideways_choices says of the table whose header is the text's first table row."""
    units = parse_manual(table, []).units
    head = next(i for i, u in enumerate(units) if u.cells and not u.header)
    return sideways_choices(units, head)


def test_capital_column_heads_over_one_quantity_each_are_a_table_written_upright() -> None:
    programmes = """| Cycle | HEAT | LENGTH |
|---|---|---|
| Linen | 70 °C | 1:45 |
| Silk | 20 °C | 0:40 |
| Rinse | 35 °C | 0:25 |
"""
    assert _sideways(programmes) is None


def test_a_table_of_one_unit_along_both_axes_is_not_read_sideways() -> None:
    """A grill's limits per programme, every amount in °C, with a "--" and a wrapped note that
    mix the columns: one unit both ways says nothing of which axis holds the choices."""
    limits = """| Programme | usual | lowest | highest |
|---|---|---|---|
| STEAK | 220 °C | 190 °C (3 clicks | 250 °C (3 clicks |
| | | down) | up) |
| FISH | 170 °C | 150 °C (2 clicks | 190 °C (2 clicks |
| | | down) | up) |
| TOAST | -- | -- | -- |
"""
    assert _sideways(limits) is None


def test_a_grid_with_a_blank_corner_is_no_keys_choices() -> None:
    spec = """| | JP | AU | CN |
|---|---|---|---|
| Mains | 100 V | 230 V | 220 V |
| Cycle rate | 50 Hz | 50 Hz | 50 Hz |
"""
    assert _sideways(spec) is None


def test_a_header_row_over_its_rows_is_no_keys_row_of_marks() -> None:
    lamps = """## Indicator lamps

| Speed | LAMP | SCREEN |
|---|---|---|
| Slow | green | S1 |
| Fast | amber | S2 |
"""
    units = parse_manual(lamps, []).units
    head = next(i for i, u in enumerate(units) if u.cells and not u.header)
    assert key_row_marks(units[head].cells, {"speed"}, units[head].header, True) is None
    assert key_row_marks(("Speed", "LOW", "HIGH"), {"speed"}) == ["LOW", "HIGH"]


def test_a_key_word_under_four_letters_names_no_row_of_marks() -> None:
    assert key_row_marks(("Run", "LOW", "HIGH"), {"run"}) is None


def test_two_capitalised_menu_entries_joined_by_and_are_no_choice() -> None:
    assert find_list("Select Alarm and Snooze to set the wake time.") is None
    assert find_list("Select Alarm or Snooze.") == (["Alarm", "Snooze"], "list")
