"""Rules of how people phrase requests (goal15), checked on models written for these tests (loaded
unchecked: only the parts a rule reads are written): a foot spa, a cigar humidor, a massage
chair, a heated blanket, a photo frame, a facial mister, a home sauna, a soundbar and an
aquarium controller — none of them in a suite. Each test would fail without its rule."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_text import Text
from apbot.read.goal_unitless import unitless_duration
from apbot.read.goal_view import model_view
from apbot.read.numbers import find_mentions


def _goal(model_text: str, said: str) -> dict[str, object]:
    return dict(parse_instruction(loads_model(model_text, check=False), said))


FOOT_SPA = """
appliance: {id: spa_1, category: foot_spa, name: "Aquarest F2 foot spa", brand: A}
controls:
  - {id: soak_key, kind: button, label: "SOAK"}
variables:
  soak:
    type: discrete
    values: ["off", "auto", "10", "20", "30"]
    show: {"off": "S OFF", "auto": "S AUTO", "10": "S 10", "20": "S 20", "30": "S 30"}
actions:
  press_soak: {control: soak_key}
features:
  soak:
    - {actions: [press_soak], variable: soak, effect: next}
"""


def test_lengths_with_an_automatic_choice_take_a_duration() -> None:
    """OFF / AUTO / 10 / 20 / 30 is still a list of lengths in minutes."""
    assert _goal(FOOT_SPA, "A twenty-minute soak, please.") == {"soak": "20"}
    assert _goal(FOOT_SPA, "Soak my feet for half an hour.") == {"soak": "30"}


HUMIDOR = """
appliance: {id: humidor_1, category: humidor, name: "Cedarline H1 humidor", brand: C}
controls:
  - {id: hum_key, kind: button, label: "HUM"}
variables:
  humidity:
    type: discrete
    values: ["off", "low", "high"]
    show: {"off": "H-", "low": "H1", "high": "H2"}
actions:
  press_hum: {control: hum_key}
features:
  humidity:
    - {actions: [press_hum], variable: humidity, effect: next}
"""


def test_the_humidifier_names_the_humidity() -> None:
    """A name in -ity is set on the thing in -ifier: "the humidifier off" is HUMIDITY off."""
    assert _goal(HUMIDOR, "Switch the humidifier off for the winter.") == {"humidity": "off"}


CHAIR = """
appliance: {id: chair_1, category: massage_chair, name: "Restwell C9 massage chair", brand: R}
controls:
  - {id: play_key, kind: button, label: "▶/■"}
  - {id: rest_key, kind: button, label: "FOOTREST"}
  - {id: mode_key, kind: button, label: "MODE"}
variables:
  massage: {type: discrete, values: ["off", "on"]}
  footrest: {type: discrete, values: ["off", "on"]}
  quietmode: {type: discrete, values: ["off", "on"]}
actions:
  press_play: {control: play_key}
  press_rest: {control: rest_key}
  hold_mode: {control: mode_key, skill: hold, seconds: 3}
features:
  massage:
    - {actions: [press_play], variable: massage, effect: toggle}
  footrest:
    - {actions: [press_rest], variable: footrest, effect: toggle}
anywhere:
  - {actions: [hold_mode], variable: quietmode, effect: toggle}
"""


def test_a_play_stop_key_starts_the_work() -> None:
    """The switch a "▶/■" key toggles is what "start" and "don't start yet" are about."""
    assert _goal(CHAIR, "Footrest on, but don't start yet.") == {"footrest": "on", "massage": "off"}


def test_a_camel_case_name_is_one_word() -> None:
    """ "QuietMode" and "quiet mode" both name the one-word QUIETMODE."""
    assert _goal(CHAIR, "Switch QuietMode on.") == {"quietmode": "on"}
    assert _goal(CHAIR, "Footrest on and turn quiet mode on.") == {
        "footrest": "on",
        "quietmode": "on",
    }


BLANKET = """
appliance: {id: blanket_1, category: heated_blanket, name: "Snugtex B4 heated blanket", brand: S}
controls:
  - {id: timer_key, kind: button, label: "TIMER"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  heat: {type: numeric, unit: "°C", ranges: [[20, 45, 1]], initial: 30}
  auto_off:
    type: discrete
    values: ["off", "30", "60", "90", "120"]
    show: {"off": "--", "30": "30", "60": "60", "90": "90", "120": "120"}
  sleep:
    type: discrete
    values: ["off", "10", "20", "30"]
    show: {"off": "Z-", "10": "Z10", "20": "Z20", "30": "Z30"}
actions:
  press_timer: {control: timer_key}
features:
  auto_off:
    - {actions: [press_timer], variable: auto_off, effect: next}
"""


def test_an_hour_and_a_half_is_ninety_listed_minutes() -> None:
    """ "an hour and a half": the unit said is the hour, the half only adds to it (checked on
    the step that reads it: other steps may reach the same goal on a model this small)."""
    view = model_view(loads_model(BLANKET, check=False))
    text = Text.of("auto off after an hour and a half")
    mention = next(m for m in find_mentions(text.tokens) if m.kind == "duration")
    goal: dict[str, object] = {}
    assert unitless_duration(view, text, mention, goal) == "auto_off"
    assert goal == {"auto_off": "90"}


FRAME = """
appliance: {id: frame_1, category: photo_frame, name: "Pixwall P8 photo frame", brand: P}
controls:
  - {id: sleep_key, kind: button, label: "SLEEP"}
variables:
  sleep:
    type: discrete
    values: ["off", "15", "30", "60"]
    initial: "15"
    show: {"off": "Z -", "15": "Z 15", "30": "Z 30", "60": "Z 60"}
actions:
  press_sleep: {control: sleep_key}
features:
  sleep:
    - {actions: [press_sleep], variable: sleep, effect: next}
"""


def test_never_let_it_sleep_is_sleep_off() -> None:
    assert _goal(FRAME, "Show the holiday album and never let it go to sleep.") == {"sleep": "off"}
    assert _goal(FRAME, "Don't let it sleep during the party.") == {"sleep": "off"}


NOISE = """
appliance: {id: mister_1, category: facial_mister, name: "Dewline M2 facial mister", brand: D}
controls:
  - {id: level_key, kind: button, label: "LEVEL"}
variables:
  level:
    type: discrete
    values: [soft, normal, loud]
    initial: normal
    show: {soft: "pH 4.5", normal: "pH 5.0", loud: "pH 5.5"}
actions:
  press_level: {control: level_key}
features:
  level:
    - {actions: [press_level], variable: level, effect: next}
"""


def test_a_value_named_by_its_display_label_and_number() -> None:
    """ "pH five": the value the display shows as "pH 5.0" (a mist of a set acidity)."""
    assert _goal(NOISE, "Keep it at pH five tonight.") == {"level": "normal"}
    assert _goal(NOISE, "pH four and a half, please.") == {"level": "soft"}


SAUNA = """
appliance: {id: sauna_1, category: home_sauna, name: "Lampo S3 home sauna", brand: L}
controls:
  - {id: dry_key, kind: button, label: "DRY"}
  - {id: steam_key, kind: button, label: "STEAM"}
variables:
  bath: {type: discrete, values: [dry_1, dry_2, dry_3, steam_1, steam_2], initial: dry_1}
actions:
  press_dry: {control: dry_key}
  press_steam: {control: steam_key}
features:
  bath:
    - {actions: [press_dry], variable: bath, effect: next}
"""


def test_numbered_levels_of_a_word() -> None:
    """Values numbered under one word are its levels: named by a level or an end of them."""
    assert _goal(SAUNA, "Dry level two tonight.") == {"bath": "dry_2"}
    assert _goal(SAUNA, "The strongest dry heat.") == {"bath": "dry_3"}
    assert _goal(SAUNA, "The milder steam for the kids.") == {"bath": "steam_1"}


SOUNDBAR = """
appliance: {id: bar_1, category: soundbar, name: "Wavecast S5 soundbar", brand: W}
controls:
  - {id: mute_key, kind: button, label: "MUTE"}
  - {id: mode_key, kind: button, label: "SOUND MODE"}
variables:
  mute: {type: discrete, values: ["off", "on"]}
  sound_mode: {type: discrete, values: [standard, night, voice]}
actions:
  press_mute: {control: mute_key}
  press_mode: {control: mode_key}
features:
  mute:
    - {actions: [press_mute], variable: mute, effect: toggle}
  sound_mode:
    - {actions: [press_mode], variable: sound_mode, effect: next}
"""


def test_mute_turns_a_mute_switch_on() -> None:
    """ "mute it" sets MUTE on: the word is the switch's own name, not a denial of sound."""
    assert _goal(SOUNDBAR, "Mute it while I take this call.") == {"mute": "on"}
    assert _goal(SOUNDBAR, "Night mode, but don't mute it.") == {
        "sound_mode": "night",
        "mute": "off",
    }


def test_a_word_of_another_settings_name_is_not_a_synonym() -> None:
    """ "voice sound mode": SOUND MODE's words, not "sound" for the MUTE switch."""
    assert _goal(SOUNDBAR, "Voice sound mode for the news.") == {"sound_mode": "voice"}


AQUARIUM = """
appliance: {id: tank_1, category: aquarium_controller, name: "Reefmate A2 controller", brand: R}
controls:
  - {id: power_key, kind: button, label: "POWER"}
  - {id: alarm_key, kind: button, label: "ALARM"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  low_alarm: {type: discrete, values: ["20", "21", "22", "23", "24"], initial: "22"}
  high_alarm: {type: numeric, unit: "°C", ranges: [[25, 32, 1]], initial: 28}
actions:
  press_power: {control: power_key}
  press_alarm: {control: alarm_key}
features:
  low_alarm:
    - {actions: [press_alarm], variable: low_alarm, effect: next}
  high_alarm:
    - {actions: [press_alarm], variable: high_alarm, effect: next}
anywhere:
  - {actions: [press_power], variable: power, effect: toggle}
"""


def test_below_and_above_are_the_low_and_high_limits() -> None:
    """ "falls below 21 degrees or rises above 30": the low and the high alarm, whichever has
    the unit."""
    assert _goal(AQUARIUM, "Alert me if the tank falls below 21 degrees or rises above 30.") == {
        "low_alarm": "21",
        "high_alarm": 30,
    }


def test_a_qualified_unit_turned_on_is_the_power() -> None:
    """ "turn the control unit on": a word before the appliance's own noun is part of its name."""
    assert _goal(AQUARIUM, "Turn the control unit on.") == {"power": "on"}


FAN = """
appliance: {id: fan_9, category: desk_fan, name: "Aerly D1 desk fan", brand: A}
controls:
  - {id: speed_key, kind: button, label: "SPEED"}
variables:
  speed: {type: discrete, values: [low, mid, high, auto], initial: low}
actions:
  press_speed: {control: speed_key}
features:
  speed:
    - {actions: [press_speed], variable: speed, effect: next}
"""


def test_a_choice_left_to_the_appliance_is_auto() -> None:
    """ "let it choose the speed": the user hands the choice over, the AUTO value."""
    assert _goal(FAN, "Let it choose the speed by itself tonight.") == {"speed": "auto"}
    assert _goal(FAN, "Let the fan pick the speed.") == {"speed": "auto"}
