"""Defects a code review found in the reader, each on a small manual of its own."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from apbot.model.validate import check_model
from apbot.read import ReaderError, read_manual
from apbot.read.clock_format import twelve_hour_clock
from apbot.read.text import parse_manual
from apbot.read.values import Range, find_ranges

KNOB = ["turn_mode_knob_clockwise", "press_start_button"]


def _checked(text: str, actions: list[str]) -> None:
    try:
        reading = read_manual(text, actions)
    except ReaderError as error:
        assert str(error).strip()
        return
    assert not [p for p in check_model(reading.model) if p.severity == "error"]


def test_a_knob_with_zero_positions_is_read_without_a_list() -> None:
    text = "# T\n\nThe MODE knob has zero positions.\n\nTurn the MODE knob to select.\n"
    model = read_manual(text, KNOB).model  # (raised ValueError: int('zero'))
    assert not [p for p in check_model(model) if p.severity == "error"]


def test_a_counted_knob_in_words_takes_the_row_of_that_many_names() -> None:
    text = "# T\n\nThe MODE knob has three positions.\n\nDRY · STEAM · GRILL\n"
    model = read_manual(text, KNOB).model
    assert model.variables["mode"].values == ["dry", "steam", "grill"]


_COUNT = st.sampled_from(["zero", "0", "00", "one", "nineteen", "12", "99", "no", "a"])
_AMOUNT = st.sampled_from(["0", "0.5", "1,5", "zero", "half", "ten", "24", "1000", "00"])
_UNIT = st.sampled_from(["min", "hours", "s", "°C", "%", "kg", "g", "W", ""])


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_COUNT, _AMOUNT, _AMOUNT, _AMOUNT, _UNIT)
def test_counted_ranged_and_stepped_phrases_with_odd_numbers_read_or_refuse(
    count: str, low: str, high: str, step: str, unit: str
) -> None:
    text = (
        f"# T\n\nThe MODE knob has {count} positions.\n\n{low} {unit} · {high} {unit}\n\n"
        f"Set the time from {low} to {high} {unit} in steps of {step} {unit}.\n\n"
        f"Each press of TIMER adds {step} {unit}, up to {high} {unit}.\n\n"
        f"| Programme | Time ({unit}) |\n|---|---|\n| BAKE | {low}–{high} |\n| GRILL | {high} |\n"
    )
    _checked(text, [*KNOB, "press_timer_button"])


TIMER_DIAL = """# Mini oven

## TIMER knob

Turning the TIMER knob starts the oven. Its dial is printed OFF 5 10 15 20 30 45 (minutes).
{said} Past that the knob clicks at the printed numbers.
"""
TIMER_ACTIONS = ["turn_timer_knob_clockwise", "turn_timer_knob_counterclockwise", "press_light"]


@pytest.mark.parametrize(
    "said",
    [
        "Up to 5 min the knob moves in 1-minute steps.",
        "For the first five minutes, each minute is marked.",
        "Below 5 minutes there is a detent minute by minute.",
    ],
)
def test_a_dial_marked_minute_by_minute_up_to_a_bound_has_every_minute_there(said: str) -> None:
    model = read_manual(TIMER_DIAL.format(said=said), TIMER_ACTIONS).model
    timer = model.variables["timer"]
    assert timer.ranges[0] == ("00:00:00", "00:05:00", 60)


def test_a_minute_counted_down_is_no_minute_by_minute_dial() -> None:
    said = "The display counts each minute down."
    model = read_manual(TIMER_DIAL.format(said=said), TIMER_ACTIONS).model
    assert model.variables["timer"].ranges[0][2] == 300


HOB = """# Hob

## Keys

| Key | Touch | Touch and hold |
|---|---|---|
| ON/OFF | Switches the hob on and off. | – |
| LEFT | Selects the left field. | Touch and hold 2 s: timer for the left cooking field. |
| RIGHT | Selects the right field. | Touch and hold 2 s: timer for the right cooking field. |
| + / − | Change the power or the timer minutes. | – |

Touch LEFT or RIGHT, then + or − to change its power level from 1 to 9.
Touch and hold LEFT or RIGHT to set that field's timer with + and −, 1 to 99 minutes.
"""
HOB_ACTIONS = [
    "press_on_off",
    "press_left",
    "hold_left",
    "press_right",
    "hold_right",
    "press_plus",
    "press_minus",
]


def test_a_hold_for_the_timer_of_a_place_of_any_noun_is_that_keys_timer() -> None:
    model = read_manual(HOB, HOB_ACTIONS).model  # ("cooking field": no fixed list of places)
    assert not [p for p in check_model(model) if p.severity == "error"]
    held = next(f for f in model.features.values() if f[0].actions == ["hold_left"])
    assert held[1].variable == "left_timer"


@pytest.mark.parametrize(
    ("said", "twelve"),
    [
        ("The clock uses the 12-Hour format.", True),
        ("Time of day is shown in 12 h format.", True),
        ("Set the clock to the time of day, e.g. 7:30 pm.", True),
        ("Keep warm runs for a 12-hour maximum.", False),
        ("Delay: up to a 12-hour delay. The clock shows 24 h.", False),
        ("I am sure the clock works.", False),
    ],
)
def test_a_twelve_hour_clock_is_read_from_any_spelling_and_only_of_a_clock(
    said: str, twelve: bool
) -> None:
    assert twelve_hour_clock(parse_manual(f"# T\n\n{said}\n").units) is twelve


COOKER = """# Cooker

## Keys

| Key | Use |
|---|---|
| MENU | Choose the menu: WHITE, BROWN, PORRIDGE, STEAM or CAKE. |
| TEXTURE | {said} |
| START | Starts cooking. |
"""
COOKER_ACTIONS = ["press_menu", "press_texture", "press_start"]


@pytest.mark.parametrize(
    ("said", "values"),
    [
        ("Selects SOFT, REGULAR or FIRM only.", ["soft", "regular", "firm"]),
        ("Choose between SOFT and FIRM only.", ["soft", "firm"]),
        ("Selects SOFT, REGULAR or FIRM (WHITE and BROWN only).", ["soft", "regular", "firm"]),
        ("Selects SOFT, REGULAR or FIRM; for WHITE, BROWN only.", ["soft", "regular", "firm"]),
    ],
)
def test_only_closes_the_programmes_a_setting_applies_to_and_nothing_else(
    said: str, values: list[str]
) -> None:
    model = read_manual(COOKER.format(said=said), COOKER_ACTIONS).model
    assert model.variables["texture"].values == values


@pytest.mark.parametrize(
    "said",
    [
        "Selects the texture (WHITE, BROWN only).",
        "Choose the texture for WHITE or BROWN only.",
        "Selects the texture. Available for the following menus only: WHITE, BROWN.",
    ],
)
def test_the_programmes_a_setting_applies_to_are_not_its_values(said: str) -> None:
    model = read_manual(COOKER.format(said=said), COOKER_ACTIONS).model
    assert "white" not in model.variables["texture"].values


STEAMER = """# Steamer

## Keys

| Key | Use |
|---|---|
| CLOCK | Sets the clock. |
| HOUR | Moves the flashing time on by one hour. |
| MIN | Moves the flashing time on by one minute. |
| COOK TIME | Opens the cooking time. |
| + / − | Change the cooking time. |
| START | Starts. |

## Setting the clock

Press CLOCK, then HOUR and MIN until the time of day is shown.

## Cooking time

Press COOK TIME, then + or − to change the cooking time from 10 to 90 minutes in 5-minute steps.
"""
STEAMER_ACTIONS = [
    "press_clock",
    "press_hour",
    "press_min",
    "press_cook_time",
    "press_plus",
    "press_minus",
    "press_start",
]


def test_hour_and_min_set_only_the_times_their_sentences_are_about() -> None:
    model = read_manual(STEAMER, STEAMER_ACTIONS).model  # (COOK TIME is a time word alone)
    clock = next(f for f in model.features.values() if f[0].actions == ["press_clock"])
    assert clock[1].actions == ["press_hour", "press_min"]
    cook = next(f for f in model.features.values() if f[0].actions == ["press_cook_time"])
    assert set(cook[1].actions) == {"press_plus", "press_minus"}
    assert model.variables["cook_time"].ranges[0][:2] == ("00:10:00", "01:30:00")


@pytest.mark.parametrize(
    ("text", "low", "high", "unit"),
    [
        ("from 0.1 kg to 1500 g", 100, 1500, "g"),
        ("from 100 g to 2 kg", 100, 2000, "g"),
        ("250 ml to 1.5 l", 250, 1500, "ml"),
    ],
)
def test_a_range_written_in_two_units_of_one_kind_is_read_in_the_smaller(
    text: str, low: float, high: float, unit: str
) -> None:
    assert find_ranges(text) == [Range(low, high, unit)]


MICRO = """# Microwave

## Keys

| Key | Use |
|---|---|
| DEFROST | Defrost by weight. |
| START | Starts. |

## Defrost

Press DEFROST repeatedly to set the weight from {said}.
"""


@pytest.mark.parametrize("said", ["0.1 to 1.5 kg in 100 g steps", "100 to 1500 g in 0.1 kg steps"])
def test_a_step_in_another_unit_of_the_range_kind_is_converted(said: str) -> None:
    model = read_manual(MICRO.format(said=said), ["press_defrost", "press_start"]).model
    var = model.variables["defrost"]
    low, high, step = var.ranges[0]
    assert high / low == 15 and high / step == 15  # 0.1–1.5 kg by 0.1, or 100–1500 g by 100


TWO_LINE_HEADER = """# Washer

| Programme | Max. temperature | Max. spin |
| | (°C) | (rpm) |
|---|---|---|
| Cotton | 40 | 1200 |
| Wool | 20 | 600 |
|---|---|---|
| Rinse | – | 800 |
"""


def test_the_lines_above_a_tables_rule_are_its_header_not_data_rows() -> None:
    rows = [u for u in parse_manual(TWO_LINE_HEADER).units if u.cells]
    assert rows[0].cells == ("Programme", "Max. temperature (°C)", "Max. spin (rpm)")
    assert [u.cells[0] for u in rows if u.header] == ["Cotton", "Wool", "Rinse"]


def test_a_table_cell_names_the_programme_it_spells_before_one_it_begins() -> None:
    from apbot.read.cases_tables import _parent_values

    values = ["white quick", "white", "brown"]
    assert _parent_values("White, Brown", values) == ["white", "brown"]
    assert _parent_values("White quick", values) == ["white quick"]
    assert _parent_values("Brow", values) == ["brown"]


MINDER = """# Oven

## Keys

| Key | Use |
|---|---|
| ALARM | Kitchen alarm. |
| 0–9 | Number keys. |
| GO | Starts. |

## Kitchen alarm

Touch ALARM, key in the minutes (up to two digits), then GO.
"""
MINDER_ACTIONS = ["press_alarm", *(f"press_{d}" for d in range(10)), "press_go"]


def test_a_time_keyed_in_two_digits_of_minutes_runs_to_99_minutes() -> None:
    model = read_manual(MINDER, MINDER_ACTIONS).model
    assert model.variables["alarm"].ranges[-1][1] == "01:39:00"


OVEN = """# Oven

## Keys

| Key | Use |
|---|---|
| TIME | Enter the cooking time. |
| 0–9 | Number keys. |
| GO | Starts. |

Touch TIME, then key in the hours and minutes.

## Technical data

Power 1500 W · Timer 0:01–9:59 (h:mm) · Mass 6 kg
"""
OVEN_ACTIONS = ["press_time", *(f"press_{d}" for d in range(10)), "press_go"]


def test_a_time_setting_takes_the_timer_range_of_the_specifications_when_no_key_is_a_timer() -> (
    None
):
    model = read_manual(OVEN, OVEN_ACTIONS).model
    ranges = model.variables["time"].ranges
    assert ranges[0][0] == "00:01:00" and ranges[-1][1] == "09:59:00"


def test_words_in_brackets_after_a_number_do_not_hide_a_range() -> None:
    said = "Heat runs from 1 (just warm) to 9 (fierce)."
    assert find_ranges(said) == [Range(1, 9, "")]
    assert find_ranges("from 40 (min) to 90 min") == []  # (a unit in brackets is no aside)


DELAYED = """# Cooker

## Keys

| Key | Use |
|---|---|
| DELAY | Sets the delay, then + / − change it. |
| + / − | Change the delay. |
| START | Starts. |

## Delay

Press DELAY, then + or −. The delay runs 0:00 – 4:00 by 15 minutes, then 4:00 – 18:00 by 1 hour.
"""


def test_time_ranges_each_with_its_step_make_a_piecewise_range() -> None:
    actions = ["press_delay", "press_plus", "press_minus", "press_start"]
    model = read_manual(DELAYED, actions).model
    assert model.variables["delay"].ranges == [
        ("00:00:00", "04:00:00", 900),
        ("04:00:00", "18:00:00", 3600),
    ]


DRYER = """# Dryer

## Keys

| Key | Use |
|---|---|
| ▲ / ▼ | Raise or lower the target humidity. |
| POWER | On and off. |

## Humidity

Press ▲ or ▼ to change the target humidity shown.

Tip: for a bedroom, 50 to 60 % is a comfortable level.

## Specifications

| Item | Value |
|---|---|
| Humidity setting | 35–75 % |
"""


def test_a_range_given_as_advice_is_not_the_settings_limits() -> None:
    model = read_manual(DRYER, ["press_up", "press_down", "press_power"]).model
    humidity = next(v for k, v in model.variables.items() if "humid" in k)
    assert humidity.ranges[0][0] == 35 and humidity.ranges[-1][1] == 75


OFF_TIMER = """# Fan heater

## Keys

| Key | Use |
|---|---|
| TIMER | Each press adds time to the switch-off timer. |
| POWER | On and off. |

## Switch-off timer

Press TIMER: each press adds time. The steps are given in the table below.

| Timer band | Range | Increment |
|---|---|---|
| Brief | 0.5 – 4 hours | half an hour |
| Extended | 4 – 12 hours | one hour |
"""


def test_a_range_table_with_an_increment_per_row_is_a_piecewise_range_not_its_row_names() -> None:
    model = read_manual(OFF_TIMER, ["press_timer", "press_power"]).model
    timer = model.variables["timer"]  # (hours)
    assert [tuple(r) for r in timer.ranges] == [(0.5, 4, 0.5), (4, 12, 1)]


def test_a_few_numbered_keys_are_no_range() -> None:
    from apbot.read.shapes import _keypad

    said = "Number pads: enter times; pads 1 to 6 also start a quick cook"
    assert _keypad(Range(1, 6, ""), said)
    assert not _keypad(Range(1, 6, ""), "Levels run from 1 to 6")
