"""Where a setting's unit is written down in a commercial manual other than beside its range:
the header of the programme table's column, a key legend or heading that calls the key a
timer. Each on a small manual of our own in that style."""

from __future__ import annotations

from apbot.model.domain import all_values
from apbot.read import read_manual
from apbot.read.goal import parse_instruction

# a twin-tub washer: the per-course limits stand in a table whose headers carry the units
WASHER = """# NORDWASH TW-8 Twin-Tub Washer — Owner's Manual

⚠ Unplug the washer before cleaning. Do not wash waterproof items.

## The keys

| Key | What it does |
|---|---|
| **PROGRAM** | Chooses the programme. |
| **SOAK** | Changes the soaking time. |
| **AGITATE** | Changes the agitation time. |
| **FINISH** | Sets in how many hours the programme ends. |
| **START** | Starts or pauses the programme. |

## Programmes

| Programme | Suited to | Soak (min) | Agitate (min) |
|---|---|---|---|
| Standard | Everyday laundry | 0 – 20 (10) | 5 – 15 (10) |
| Strong | Very dirty clothes | 10 – 40 (20) | 10 – 20 (15) |
| Gentle | Wool, silk | 0 – 10 (0) | 3 – 6 (3) |

Press SOAK or AGITATE and every press gives the next value; after the longest the shortest
comes back.

## Finishing later

Press FINISH: the display shows the hours, 2 to 12.
"""

WASHER_ACTIONS = ["press_program", "press_soak", "press_agitate", "press_finish", "press_start"]


def test_a_column_headed_with_its_unit_gives_the_dependent_amount_that_unit() -> None:
    model = read_manual(WASHER, WASHER_ACTIONS).model
    soak = model.variables["soak"]
    assert soak.depends_on == "program"
    assert getattr(soak, "unit", "") == "min"
    assert getattr(model.variables["agitate"], "unit", "") == "min"


def test_a_duration_bound_to_its_noun_goes_to_that_setting_not_the_hour_timer() -> None:
    model = read_manual(WASHER, WASHER_ACTIONS).model
    goal = parse_instruction(
        model, "Strong programme with a 30-minute soak and 12 minutes of agitation, start it."
    )
    assert goal.get("soak") == 30 and goal.get("agitate") == 12
    assert "finish" not in goal


# a bread maker whose ready-in key is called a timer only in its legend and in a heading,
# and whose limit is told only on the specifications line
BREAD = """# CRUSTA BM-15 Bread Maker

| Pad | Use |
|---|---|
| MENU | Selects one of the 12 menus |
| RESERVE | Timer: hours until the bread is done |
| START/STOP | Starts or stops the menu |

## Ready-in timer (RESERVE)

Touch RESERVE repeatedly to choose in how many hours the bread should be done. Each touch adds
time; past the maximum the timer returns to 0.

## Specifications

230 V ~ 50 Hz · 600 W · loaf 1.0–2.0 LB · timer up to 13 h in whole hours · 12 menus
"""


def test_a_key_its_legend_calls_a_timer_takes_the_timer_range_of_the_specifications() -> None:
    model = read_manual(BREAD, ["press_menu", "press_reserve", "press_start_stop"]).model
    reserve = model.variables["reserve"]
    assert getattr(reserve, "unit", "") == "h"
    values = all_values(reserve)
    assert values[0] == 0 and values[-1] == 13  # not the loaf's 1.0–2.0 LB on the same line


def test_a_legend_that_only_mentions_a_timer_later_does_not_make_a_key_a_time() -> None:
    text = BREAD.replace("Timer: hours until the bread is done", "Crust shade; see the timer")
    text = text.replace("## Ready-in timer (RESERVE)", "## Crust shade (RESERVE)")
    model = read_manual(text, ["press_menu", "press_reserve", "press_start_stop"]).model
    assert getattr(model.variables["reserve"], "unit", "") != "h"


def test_numbers_read_bare_take_the_unit_printed_beside_them_where_the_setting_is_named() -> None:
    text = """# HEARTH BM-3 Bread Maker

| Pad | Use |
|---|---|
| SIZE | Chooses the size of the finished loaf. |
| START | Starts the programme. |

The display points at the printed sizes (450 / 680 / 900) with a small arrow.

| Programme | Time | Size |
|---|---|---|
| Basic | 3:00 | 450 / 680 / 900 g |
| Rapid | 1:58 | 680 / 900 g |
"""
    model = read_manual(text, ["press_size", "press_start"]).model
    size = model.variables["size"]
    assert getattr(size, "unit", "") == "g"
    goal = parse_instruction(model, "A 680 g loaf please.")
    assert goal.get("size") == 680


def test_a_bare_number_setting_takes_no_unit_from_a_line_that_does_not_name_it() -> None:
    text = """# HEARTH BM-3 Bread Maker

| Pad | Use |
|---|---|
| CRUST | Chooses the crust: 1, 2 or 3 bars. |
| START | Starts the programme. |

Rated power 3 W in standby.
"""
    model = read_manual(text, ["press_crust", "press_start"]).model
    assert getattr(model.variables["crust"], "unit", "") == ""


# a multicooker whose delay is keyed in on the number pad; its step is told in a sentence led by
# the setting's name, three sentences after the key is named
COOKER = """# VESTA MC-10 Multicooker

## 5.3 Delayed cooking

1. Choose the program.
2. Touch DELAY. The display shows 0:00.
3. Enter the hours and minutes on the number pad, for example 6, 3, 0 for 6 hours 30 minutes.
The delay is set in half-hour units.
4. Touch START.

The delay can be used for up to 12 hours.
"""


def test_a_step_in_half_hour_units_told_by_a_sentence_led_by_the_settings_name() -> None:
    actions = ["press_delay", "press_start"] + [f"press_{d}" for d in range(10)]
    model = read_manual(COOKER, actions).model
    delay = model.variables["delay"]
    assert delay.type == "time"  # keyed in as hours and minutes
    values = all_values(delay)
    assert "06:30:00" in values and "06:15:00" not in values and values[-1] == "12:00:00"
    goal = parse_instruction(model, "Have it ready in six and a half hours, start it.")
    assert goal.get("delay") == "06:30:00"


def test_units_without_a_unit_of_measure_are_no_step() -> None:
    from apbot.read.value_steps import find_step

    assert find_step("The delay is set in half-hour units.") == (0.5, "h")
    assert find_step("The filters are sold in 2 units.") is None


def test_a_step_that_changes_part_way_told_in_words_gives_two_pieces() -> None:
    text = """# OKRA RC-2 Rice Cooker

## Delayed start

1. Choose the function.
2. Press TIMER. 0:00 flashes.
3. Press + or -. Up to two hours, each press changes the time by 15 minutes; beyond that it
   changes by 1 hour. The longest delay is 12 hours.
4. Press START.
"""
    model = read_manual(text, ["press_timer", "press_plus", "press_minus", "press_start"]).model
    values = all_values(model.variables["timer"])
    assert values[:3] == ["00:00:00", "00:15:00", "00:30:00"]
    assert "01:45:00" in values and "02:15:00" not in values and "03:00:00" in values
    assert values[-1] == "12:00:00"


# a countertop oven whose TIME pad hands the keypad the cooking time; a table shows what to type
OVEN = """# SOLANO CO-9 Countertop Oven

The keypad (1 2 3 / 4 5 6 / 7 8 9 / 0) only responds after TEMP or TIME has been touched.

## Entering the temperature

1. Touch **TEMP**. The temperature flashes.
2. Type the temperature on the keypad, 50 °C to 230 °C in steps of 5 degrees.

## Entering the cooking time

1. Touch **TIME**. The time flashes.
2. Type the hours and minutes; the last two digits you type are the minutes:

| You type | Display | Cooking time |
|---|---|---|
| 9 | 0:09 | 9 minutes |
| 1 1 5 | 1:15 | 1 hour 15 minutes |
| 4 0 0 | 4:00 | 4 hours |

During cooking you may enter a new temperature or time (TEMP or TIME, then the digits), and
switch the lamp on or off.
"""
OVEN_ACTIONS = ["press_temp", "press_time", "press_light"] + [f"press_{d}" for d in range(10)]


def test_a_table_of_what_to_type_is_examples_not_the_values_there_are() -> None:
    model = read_manual(OVEN, OVEN_ACTIONS).model
    time = model.variables["time"]
    assert time.type == "time"
    assert getattr(time, "entry", None) is not None  # TIME, then the number keys
    assert "00:10:00" in all_values(time)  # not only the three examples
    entered = [f for f in model.features.values() if any("press_1" in s.actions for s in f)]
    assert len(entered) == 2  # TEMP's and TIME's; no third time the digits set directly


def test_a_plural_ending_in_a_column_heading_is_no_unit_of_seconds() -> None:
    from apbot.read.cases_amounts import _header_unit

    plural: dict[str, object] = {"type": "numeric"}
    _header_unit(plural, "Option(s)")
    assert "unit" not in plural
    for header, unit in (("Rinse (s)", "s"), ("Soak (min)", "min"), ("Time(min)", "min")):
        spec: dict[str, object] = {"type": "numeric"}
        _header_unit(spec, header)
        assert spec["unit"] == unit, header


KEYPAD_OVEN = """# Zapwave M-1 microwave

## Cooking

Press COOK TIME, then type the cooking time with the number keys and press START.
{range}
"""
KEYPAD_ACTIONS = ["press_cook_time", "press_start"] + [f"press_{i}" for i in range(10)]


def test_a_keypad_cooking_time_is_minutes_and_seconds_only_when_no_range_was_read() -> None:
    stated = read_manual(
        KEYPAD_OVEN.format(range="The cooking time can be set from 1 to 60 minutes."),
        KEYPAD_ACTIONS,
    ).model.variables["cook_time"]
    assert stated.ranges == [("00:01:00", "01:00:00", 60)]  # type: ignore[union-attr]
    unstated = read_manual(KEYPAD_OVEN.format(range=""), KEYPAD_ACTIONS).model
    assert unstated.variables["cook_time"].format == "mm:ss"  # type: ignore[union-attr]


def test_a_step_that_changes_part_way_is_read_in_other_wordings() -> None:
    from apbot.read.values import Range
    from apbot.read.values_pieces import find_two_steps

    expected = [Range(0, 60, "min", 10), Range(60, 1440, "min", 30)]
    for wording in (
        "The delay is set in steps of 10 minutes up to 1 hour, then in steps of 30 minutes "
        "up to 24 hours.",
        "In 10-minute steps up to one hour and in 30-minute steps up to 24 hours.",
        "From 0 to 1 hour the delay changes by 10 minutes, from 1 to 24 hours by 30 minutes.",
    ):
        found = find_two_steps([wording])
        assert found is not None and found[0] == expected, wording
    told = ["Up to 1 hour the delay changes by 10 minutes; after that by 30 minutes."]
    assert find_two_steps([*told, "The longest delay is 24 hours."]) is not None
    # a maximum two sentences on belongs to the setting only when it names it
    far = [*told, "Press START.", "The longest cooking time is 9 hours."]
    assert find_two_steps(far, ("delay",)) is None
    named = [*told, "Press START.", "The longest delay is 24 hours."]
    assert find_two_steps(named, ("delay",)) == (expected, 0)
