"""General phrasings the goal parser met on appliances of new kinds: units in days and weeks,
level settings with an OFF value, compounds, waits and times of day. Every sentence and the
model are written for these tests (a proofing cabinet no suite has)."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

CABINET = """
appliance:
  {id: proofer_1, category: proofing_cabinet, name: "Levain PB-3 proofing cabinet", brand: Levain}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: mode_button, kind: button, label: "MODE"}
  - {id: mist_button, kind: button, label: "MIST"}
  - {id: fan_button, kind: button, label: "FAN"}
  - {id: days_button, kind: button, label: "DAYS"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
  - {id: clock_button, kind: button, label: "CLOCK"}
  - {id: autostop_button, kind: button, label: "AUTO STOP"}
  - {id: start_button, kind: button, label: "START"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  mode:
    type: discrete
    values: [dough, yogurt, tempeh, cheese]
  mist:
    type: discrete
    values: ["off", gentle, normal, heavy]
    initial: normal
  fan:
    type: discrete
    values: [low, medium, high]
  ferment_days:
    type: numeric
    unit: d
    ranges: [[1, 30, 1]]
    label: "DAYS"
  clock:
    type: time
    ranges: [["00:00:00", "23:59:00", 60]]
    wrap: true
    format: "hh:mm"
  auto_stop:
    type: discrete
    values: ["on", "off"]
  running:
    type: discrete
    values: ["off", "on"]
actions:
  press_power: {control: power_button}
  press_mode: {control: mode_button}
  press_mist: {control: mist_button}
  press_fan: {control: fan_button}
  press_days: {control: days_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_clock: {control: clock_button}
  hold_autostop: {control: autostop_button, skill: hold, seconds: 3}
  press_start: {control: start_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  mist:
    - {actions: [press_mist], variable: mist, effect: next}
  fan:
    - {actions: [press_fan], variable: fan, effect: next}
  days:
    - {actions: [press_days]}
    - actions: [press_up, press_down]
      variable: ferment_days
      effect: {press_up: next, press_down: prev}
  clock:
    - {actions: [press_clock]}
    - actions: [press_up, press_down]
      variable: clock
      effect: {press_up: next, press_down: prev}
  auto_stop:
    - {actions: [hold_autostop], variable: auto_stop, effect: toggle}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
display:
  idle: "{clock}"
"""


@pytest.fixture(scope="module")
def cabinet() -> ApplianceModel:
    return loads_model(CABINET)


@pytest.mark.parametrize(
    ("text", "days"),
    [
        ("Tempeh for two weeks", 14),
        ("Cheese for a fortnight", 14),
        ("Dough, 3 wks", 21),
        ("Yogurt for a week", 7),
        ("Tempeh, 4 days", 4),
    ],
)
def test_days_and_weeks_fill_a_setting_counted_in_days(
    cabinet: ApplianceModel, text: str, days: int
) -> None:
    assert parse_instruction(cabinet, text)["ferment_days"] == days


@pytest.mark.parametrize(
    "text",
    ["Dough, and no mist at all", "Dough without any mist", "Dough, mist off", "Turn off the mist"],
)
def test_a_level_setting_said_off_takes_its_off_value(cabinet: ApplianceModel, text: str) -> None:
    assert parse_instruction(cabinet, text)["mist"] == "off"


@pytest.mark.parametrize(
    ("text", "mist"),
    [
        ("Dough with as much mist as it can make", "heavy"),
        ("Dough, the maximum mist", "heavy"),
        ("Dough, the lowest mist", "gentle"),  # the lowest that mists, not off
    ],
)
def test_named_levels_from_off_up_are_a_scale(
    cabinet: ApplianceModel, text: str, mist: str
) -> None:
    assert parse_instruction(cabinet, text)["mist"] == mist


def test_a_comparison_names_only_the_setting_inside_it(cabinet: ApplianceModel) -> None:
    assert parse_instruction(cabinet, "Fan as low as it goes")["fan"] == "low"
    goal = parse_instruction(cabinet, "Proof the dough as much as the mist allows")
    assert "mist" not in goal and "fan" not in goal


EGG_BOILER = """
appliance: {id: egg_1, category: egg_boiler, name: "Ovo 6 egg boiler", brand: Ovo}
controls:
  - {id: timer_button, kind: button, label: "BOIL TIME"}
  - {id: go_button, kind: button, label: "GO"}
variables:
  boil_time:
    type: time
    ranges: [["00:04:00", "00:12:00", 60]]
    format: "mm:ss"
  boil_time_hold:
    type: discrete
    values: ["on", "off"]
  boiling:
    type: discrete
    values: ["off", "on"]
actions:
  press_timer: {control: timer_button}
  hold_timer: {control: timer_button, skill: hold, seconds: 2}
  press_go: {control: go_button}
features:
  boil_time:
    - {actions: [press_timer], variable: boil_time, effect: next}
  chime:
    - {actions: [hold_timer], variable: boil_time_hold, effect: toggle}
  go:
    - {actions: [press_go], variable: boiling, effect: toggle}
"""

EGG_MANUAL = """THE KEYS

BOIL TIME   Steps through the boiling times, one minute a press. Keep it held
            for two seconds to turn the chime on or off.
GO          Starts boiling.
"""


def test_a_legend_continued_on_the_next_line_names_what_a_hold_switches() -> None:
    model = loads_model(EGG_BOILER)
    goal = parse_instruction(model, "Eight minutes of boil time and no chime", EGG_MANUAL)
    assert goal["boil_time"] == "00:08:00" and goal["boil_time_hold"] == "off"
    # its own words still name the timer only
    assert "boil_time_hold" not in parse_instruction(model, "Boil time 6 minutes", EGG_MANUAL)


def test_general_words_for_ends_and_values(cabinet: ApplianceModel) -> None:
    assert parse_instruction(cabinet, "Dough, the heaviest mist")["mist"] == "heavy"
    purifier = loads_model(CABINET.replace("tempeh", "purify"))
    assert parse_instruction(purifier, "Just clean the air")["mode"] == "purify"


def test_a_scale_word_grading_another_word_is_no_level(cabinet: ApplianceModel) -> None:
    assert "fan" not in parse_instruction(cabinet, "Cheese for a medium-rare burger")
    assert "fan" not in parse_instruction(cabinet, "Low-fat yogurt for 2 days")
    assert parse_instruction(cabinet, "Cheese with the fan on medium")["fan"] == "medium"


@pytest.mark.parametrize(
    "text",
    [
        "Tempeh for 2 days, but wait with the start",
        "Set up tempeh and hold off on starting it",
    ],
)
def test_a_start_put_off_is_no_start(cabinet: ApplianceModel, text: str) -> None:
    assert parse_instruction(cabinet, text)["running"] == "off"


def test_when_something_begins_is_no_start(cabinet: ApplianceModel) -> None:
    goal = parse_instruction(cabinet, "Our trip starting tomorrow is 3 days long: cheese mode")
    assert "running" not in goal and goal["ferment_days"] == 3


@pytest.mark.parametrize(
    ("text", "clock"),
    [
        ("Cheese, and set the time to 9:05 pm", "21:05:00"),
        ("The correct time is 7:15 am; yogurt please", "07:15:00"),
        ("It's 6:40 now, put the clock right", "06:40:00"),
    ],
)
def test_the_time_of_day_is_the_clock(cabinet: ApplianceModel, text: str, clock: str) -> None:
    goal = parse_instruction(cabinet, text)
    assert goal["clock"] == clock and "running" not in goal


def test_by_a_time_of_day_is_when_it_should_be_ready() -> None:
    model = loads_model(CABINET.replace("clock", "ready").replace("CLOCK", "READY"))
    goal = parse_instruction(model, "Have the yogurt set by 7 in the morning")
    assert goal["ready"] == "07:00:00"


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("Dough, and stop it from switching itself off overnight", "off"),
        ("Dough; don't let it shut itself off", "off"),
        ("Dough, and let it turn itself off when done", "on"),
    ],
)
def test_switching_itself_off_names_the_automatic_switch_off(
    cabinet: ApplianceModel, text: str, value: str
) -> None:
    assert parse_instruction(cabinet, text)["auto_stop"] == value


def test_keeping_it_cold_is_a_keep_cool_switch() -> None:
    model = loads_model(CABINET.replace("auto_stop", "keep_cool").replace("AUTO STOP", "KEEP COOL"))
    goal = parse_instruction(model, "Start the yogurt and keep it chilled afterwards")
    assert goal["keep_cool"] == "on"


def test_a_superlative_restated_by_a_number_leaves_it_to_the_number(
    cabinet: ApplianceModel,
) -> None:
    goal = parse_instruction(cabinet, "Yogurt with the fan at the maximum of 20 days")
    assert goal == {"mode": "yogurt", "ferment_days": 20}


def test_a_value_cut_short_is_named_by_a_synonym_of_its_full_word() -> None:
    model = loads_model(CABINET.replace("cheese]", '"ster+dry"]'))
    assert parse_instruction(model, "A steam-and-dry run for the jars")["mode"] == "ster+dry"


def test_soft_to_firm_is_a_scale_and_the_least_of_two_levels_is_not_off() -> None:
    model = loads_model(
        CABINET.replace("fan: \n", "fan:\n")
        .replace("values: [low, medium, high]", "values: [soft, medium, firm]")
        .replace(
            'values: ["off", gentle, normal, heavy]\n    initial: normal', 'values: ["off", gentle]'
        )
    )
    goal = parse_instruction(model, "Dough with the firmest fan and the least mist")
    assert goal["fan"] == "firm" and goal["mist"] == "gentle"


def test_a_programme_number_names_the_value_the_display_codes() -> None:
    model = loads_model(
        CABINET.replace(
            "values: [dough, yogurt, tempeh, cheese]",
            'values: [dough, yogurt, tempeh, cheese]\n    show: {dough: "F1", yogurt: "F2", '
            'tempeh: "F3", cheese: "F4"}',
        )
    )
    assert parse_instruction(model, "Put it on mode 3 for two days") == {
        "mode": "tempeh",
        "ferment_days": 2,
    }


def test_more_general_words(cabinet: ApplianceModel) -> None:
    goal = parse_instruction(cabinet, "Dough; don't let it turn off by itself")
    assert goal["auto_stop"] == "off"
    away = loads_model(CABINET.replace("tempeh", "holiday"))
    assert parse_instruction(away, "Vacation mode for a week") == {
        "mode": "holiday",
        "ferment_days": 7,
    }
    locking = loads_model(CABINET.replace("auto_stop", "child_lock").replace("AUTO STOP", "LOCK"))
    assert parse_instruction(locking, "Child-proof the buttons")["child_lock"] == "on"


@pytest.mark.parametrize(
    ("text", "power"),
    [
        ("Switch the cabinet off.", "off"),
        ("Turn it off", "off"),
        ("Dough, and turn it off when it's done", None),
        ("Dough; switch it off after 2 days", None),
    ],
)
def test_switching_the_appliance_off_now(cabinet: ApplianceModel, text: str, power: str) -> None:
    assert parse_instruction(cabinet, text).get("power") == power


def test_a_word_of_another_settings_name_is_not_a_level_said_off(cabinet: ApplianceModel) -> None:
    model = loads_model(CABINET.replace("auto_stop", "fan_mist").replace("AUTO STOP", "FAN MIST"))
    assert "mist" not in parse_instruction(model, "Dough, with the fan mist off")
