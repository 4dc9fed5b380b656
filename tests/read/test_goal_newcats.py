"""Phrasings the goal parser missed on the second set of new categories, each checked on a
model and sentences written for these tests (a sandwich press and a tabletop fan-heater no
suite has): timers whose values are hours shown as "2H", a switch whose own name ends in
"-off", "let it switch off afterwards", and everyday words for positions and levels."""

from __future__ import annotations

import pytest

from apbot.model.load import loads_model
from apbot.model.schema import ApplianceModel
from apbot.read.goal import parse_instruction

PRESS = """
appliance: {id: press_1, category: sandwich_press, name: "Toastie TP-2 sandwich press", brand: T}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: side_button, kind: button, label: "SIDE"}
  - {id: fan_button, kind: button, label: "FAN"}
  - {id: lamp_button, kind: button, label: "LAMP"}
  - {id: hours_button, kind: button, label: "HOURS"}
  - {id: autooff_button, kind: button, label: "AUTO OFF"}
  - {id: start_button, kind: button, label: "START"}
  - {id: boost_button, kind: button, label: "FAN BOOST"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  fan_boost:
    type: discrete
    values: ["off", "on"]
  side:
    type: discrete
    values: [both, lower, upper]
  fan:
    type: discrete
    values: [low, mid, high]
  lamp:
    type: discrete
    values: ["off", dim, bright]
  hours:
    type: discrete
    values: ["off", "1", "3", "6"]
    show: {"off": "", "1": "1H", "3": "3H", "6": "6H"}
  auto_off:
    type: discrete
    values: ["off", "on"]
    show: {"off": "", "on": "AUTO OFF"}
  running:
    type: discrete
    values: ["off", "on"]
actions:
  press_power: {control: power_button}
  press_side: {control: side_button}
  press_fan: {control: fan_button}
  press_lamp: {control: lamp_button}
  press_hours: {control: hours_button}
  press_autooff: {control: autooff_button}
  press_start: {control: start_button}
  hold_boost: {control: boost_button, skill: hold, seconds: 3}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  fan_boost:
    - {actions: [hold_boost], variable: fan_boost, effect: toggle}
  side:
    - {actions: [press_side], variable: side, effect: next}
  fan:
    - {actions: [press_fan], variable: fan, effect: next}
  lamp:
    - {actions: [press_lamp], variable: lamp, effect: next}
  hours:
    - {actions: [press_hours], variable: hours, effect: next}
  auto_off:
    - {actions: [press_autooff], variable: auto_off, effect: toggle}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def press() -> ApplianceModel:
    return loads_model(PRESS)


@pytest.mark.parametrize(
    ("text", "hours"),
    [("Stop after three hours", "3"), ("hours: 6 h", "6"), ("off in an hour", "1")],
)
def test_a_timer_of_hours_shown_as_codes_takes_a_duration(
    press: ApplianceModel, text: str, hours: str
) -> None:
    assert parse_instruction(press, text)["hours"] == hours


@pytest.mark.parametrize(
    ("text", "state"),
    [
        ("Turn the automatic shut-off on", "on"),
        ("switch on auto-off", "on"),
        ("Toast it and let it switch off afterwards", "on"),
        ("Toast it, and power off when it's done", "on"),
        ("no auto-off please", "off"),
        ("turn the auto-off off", "off"),
    ],
)
def test_a_switch_named_off_is_on_unless_said_off(
    press: ApplianceModel, text: str, state: str
) -> None:
    assert parse_instruction(press, text)["auto_off"] == state


@pytest.mark.parametrize(
    ("text", "name", "value"),
    [
        ("Heat the bottom side only", "side", "lower"),
        ("just the top side", "side", "upper"),
        ("fan on slow", "fan", "low"),
        ("a medium fan", "fan", "mid"),
        ("the lamp on full", "lamp", "bright"),
    ],
)
def test_everyday_words_for_positions_and_levels(
    press: ApplianceModel, text: str, name: str, value: str
) -> None:
    assert parse_instruction(press, text)[name] == value


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("the fan on high, the lamp dim", {"fan": "high", "lamp": "dim"}),
        ("a medium fan with the fan boost on", {"fan": "mid", "fan_boost": "on"}),
        ("fan boost please", {"fan_boost": "on"}),
    ],
)
def test_a_word_shared_with_a_level_given_a_value_is_not_the_switch(
    press: ApplianceModel, text: str, goal: dict[str, str]
) -> None:
    assert parse_instruction(press, text) == goal


def test_a_slow_compound_grades_another_word(press: ApplianceModel) -> None:
    assert "fan" not in parse_instruction(press, "slow-cook the cheese, both sides")


SOUP = """
appliance: {id: soup_1, category: soup_maker, name: "Potage SM-1 soup maker", brand: P}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: menu_button, kind: button, label: "MENU"}
  - {id: cool_button, kind: button, label: "AFTER COOL"}
  - {id: start_button, kind: button, label: "START"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  programme:
    type: discrete
    values: [soup, chunky, compote, sauce]
  after_cool:
    type: discrete
    values: ["off", "on"]
  running:
    type: discrete
    values: ["off", "on"]
actions:
  press_power: {control: power_button}
  press_menu: {control: menu_button}
  press_cool: {control: cool_button}
  press_start: {control: start_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  programme:
    - {actions: [press_menu], variable: programme, effect: next}
  after_cool:
    - {actions: [press_cool], variable: after_cool, effect: toggle}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def soup() -> ApplianceModel:
    return loads_model(SOUP)


@pytest.mark.parametrize(
    ("text", "programme"),
    [
        ("A chunky soup please", "chunky"),
        ("Pea soup on the chunky setting", "chunky"),
        ("Tomato soup", "soup"),
    ],
)
def test_a_value_named_like_the_appliance_gives_way_to_another_said(
    soup: ApplianceModel, text: str, programme: str
) -> None:
    assert parse_instruction(soup, text)["programme"] == programme


def test_keep_it_with_a_word_of_the_switchs_warmth(soup: ApplianceModel) -> None:
    assert parse_instruction(soup, "Compote, and keep it cold once it's done")["after_cool"] == "on"


@pytest.mark.parametrize(
    ("text", "running"),
    [
        ("Sauce, and switch it on to run", "on"),
        ("Chunky soup, then set it running", "on"),
        ("Sauce, but leave it stopped until I'm back", "off"),
        ("Soup programme; keep it paused for now", "off"),
        ("Sauce. Leave it off for now.", "off"),
        ("Smooth soup - set it up but wait for me to start.", "off"),
    ],
)
def test_running_said_with_other_verbs(soup: ApplianceModel, text: str, running: str) -> None:
    goal = parse_instruction(soup, text)
    assert goal["running"] == running
    assert "power" not in goal


CUSHION = """
appliance: {id: cushion_1, category: heated_cushion, name: "Cosy HC-5 heated cushion", brand: C}
controls:
  - {id: power_button, kind: button, label: "POWER"}
  - {id: area_button, kind: button, label: "AREA"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
  - {id: hours_button, kind: button, label: "OFF TIMER"}
  - {id: lock_button, kind: button, label: "LOCK"}
variables:
  power:
    type: discrete
    values: ["off", "on"]
  area:
    type: discrete
    values: [back, foot]
  heat:
    type: numeric
    depends_on: area
    cases:
      back: {ranges: [[1, 5, 1]], initial: 2}
      foot: {ranges: [[1, 5, 1]], initial: 2}
  off_timer:
    type: numeric
    unit: h
    ranges: [[1, 8, 1]]
  key_lock:
    type: discrete
    values: ["off", "on"]
actions:
  press_power: {control: power_button}
  press_area: {control: area_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_hours: {control: hours_button}
  press_lock: {control: lock_button}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  area:
    - {actions: [press_area], variable: area, effect: next}
  heat:
    - actions: [press_up, press_down]
      variable: heat
      effect: {press_up: next, press_down: prev}
  off_timer:
    - {actions: [press_hours], variable: off_timer, effect: next}
  key_lock:
    - {actions: [press_lock], variable: key_lock, effect: toggle}
display:
  idle: ""
"""


@pytest.fixture(scope="module")
def cushion() -> ApplianceModel:
    return loads_model(CUSHION)


@pytest.mark.parametrize(
    ("text", "area", "heat"),
    [
        ("the back area at 4", "back", 4),
        ("My feet are cold: the foot part on maximum", "foot", 5),
        ("Feet on the lowest, please", "foot", 1),
    ],
)
def test_a_number_or_superlative_after_a_zone_is_that_zones_level(
    cushion: ApplianceModel, text: str, area: str, heat: int
) -> None:
    goal = parse_instruction(cushion, text)
    assert (goal["area"], goal["heat"]) == (area, heat)


def test_a_negation_does_not_reach_over_and_a_new_verb(cushion: ApplianceModel) -> None:
    goal = parse_instruction(cushion, "Switch off after 3 hours and lock the keys")
    assert goal == {"off_timer": 3, "key_lock": "on"}


LOOM = """
appliance: {id: loom_1, category: band_loom, name: "Weft BL-8 band loom", brand: W}
controls:
  - {id: k1, kind: key, label: "1"}
  - {id: k2, kind: key, label: "2"}
  - {id: ok_button, kind: button, label: "OK"}
  - {id: wider_button, kind: button, label: "BAND +"}
  - {id: narrower_button, kind: button, label: "BAND -"}
  - {id: shuttle_button, kind: button, label: "SHUTTLE"}
variables:
  pattern:
    type: numeric
    ranges: [[1, 12, 1]]
    entry: {format: number, max_digits: 2, overflow: shift, other_keys: clear, shows: typed}
  band_width:
    type: numeric
    unit: mm
    ranges: [[5, 40, 2.5]]
  shuttle:
    type: discrete
    values: [up, down]
actions:
  press_1: {control: k1, digit: 1}
  press_2: {control: k2, digit: 2}
  press_ok: {control: ok_button}
  press_wider: {control: wider_button}
  press_narrower: {control: narrower_button}
  press_shuttle: {control: shuttle_button}
features:
  pattern:
    - actions: [press_1, press_2, press_ok]
      variable: pattern
      effect: {press_1: digit, press_2: digit, press_ok: none}
  band_width:
    - actions: [press_wider, press_narrower]
      variable: band_width
      effect: {press_wider: next, press_narrower: prev}
  shuttle:
    - {actions: [press_shuttle], variable: shuttle, effect: toggle}
display:
  idle: "{pattern}"
"""

LOOM_MANUAL = """
PATTERN CHART

  No.   Pattern            Suits                    Band (mm)
  ---   ----------------   ----------------------   ---------
  01    Plain weave        belts, straps            12.5
  02    Twill              bag handles              10.0
  03    Herringbone        guitar straps            25.0
  04    Chevron            bookmarks                12.5
  11    Diamond eye        trims                    7.5
  12    Checkerboard       lanyards                 10.0
"""


@pytest.fixture(scope="module")
def loom() -> ApplianceModel:
    return loads_model(LOOM)


@pytest.mark.parametrize(
    ("text", "goal"),
    [
        ("Herringbone, 20 mm wide", {"pattern": 3, "band_width": 20}),
        ("a chevron band", {"pattern": 4}),
        ("Set up the checkerboard", {"pattern": 12}),
        ("the diamond eye pattern, 10 mm", {"pattern": 11, "band_width": 10}),
    ],
)
def test_a_numbered_chart_names_the_numbers_of_the_setting_it_heads(
    loom: ApplianceModel, text: str, goal: dict[str, object]
) -> None:
    assert parse_instruction(loom, text, LOOM_MANUAL) == goal


def test_a_measure_in_a_chart_is_not_a_code(loom: ApplianceModel) -> None:
    from apbot.read.goal_manual import coded_names

    names = coded_names(loom, LOOM_MANUAL)
    assert (("pattern", 12, "Checkerboard")) in names
    assert all(not name[2][:1].isdigit() for name in names)
