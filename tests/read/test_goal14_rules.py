"""Rules of how people phrase requests (goal14), checked on models written for these tests (loaded
unchecked: only the parts a rule reads are written): a record lathe, a smart water bottle, a
tower fan — none of them in a suite. Each test would fail without its rule."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

LATHE = """
appliance: {id: lathe_1, category: lathe, name: "Spinwell L1 pottery wheel", brand: S}
controls:
  - {id: up, kind: button, label: "+"}
  - {id: go, kind: button, label: "RUN"}
variables:
  speed: {type: numeric, ranges: [[20, 250, 1]], initial: 60, show: "{value}"}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_up: {control: up}
  press_go: {control: go}
features:
  speed:
    - {actions: [press_up], variable: speed, effect: next}
anywhere:
  - {actions: [press_go], variable: running, effect: toggle}
"""

BOTTLE = """
appliance: {id: bottle_1, category: water_bottle, name: "Sipwise B2 smart bottle", brand: S}
controls:
  - {id: remind_key, kind: button, label: "REMIND"}
  - {id: glow_key, kind: button, label: "GLOW"}
variables:
  reminder:
    type: discrete
    values: ["off", "30", "60", "90", "120"]
    show: {"off": "R --", "30": "R 30", "60": "R 60", "90": "R 90", "120": "R120"}
  glow: {type: discrete, values: ["off", "on"]}
actions:
  press_remind: {control: remind_key}
  press_glow: {control: glow_key}
features:
  reminder:
    - {actions: [press_remind], variable: reminder, effect: next}
  glow:
    - {actions: [press_glow], variable: glow, effect: toggle}
"""

FAN = """
appliance: {id: fan_1, category: tower_fan, name: "Breezeline T5 tower fan", brand: B}
controls:
  - {id: speed_key, kind: button, label: "SPEED"}
  - {id: sleep_key, kind: button, label: "SLEEP"}
variables:
  speed: {type: numeric, ranges: [[1, 5, 1]], initial: 3, show: "S{value}"}
  sleep:
    type: discrete
    values: ["off", "30", "60", "240"]
    show: {"off": "", "30": "z30", "60": "z60", "240": "z240"}
actions:
  press_speed: {control: speed_key}
  press_sleep: {control: sleep_key}
features:
  speed:
    - {actions: [press_speed], variable: speed, effect: next}
  sleep:
    - {actions: [press_sleep], variable: sleep, effect: next}
"""


def _goal(model_text: str, said: str) -> dict[str, object]:
    return dict(parse_instruction(loads_model(model_text, check=False), said))


def test_a_hundred_counts_one_hundred() -> None:
    """ "a hundred and twenty": the article is the count of hundreds, not a lone "one"."""
    assert _goal(LATHE, "Spin the wheel at a hundred and twenty.")["speed"] == 120
    assert _goal(LATHE, "Throw at a hundred, don't start it yet.")["speed"] == 100


def test_a_lone_article_is_still_no_number() -> None:
    assert "speed" not in _goal(LATHE, "Give it a spin.")


def test_hourly_is_every_hour() -> None:
    """ "an hourly reminder" on a list of minutes OFF / 30 / 60 …: the 60."""
    assert _goal(BOTTLE, "An hourly reminder, please.")["reminder"] == "60"


def test_every_hour_and_a_half() -> None:
    assert _goal(BOTTLE, "Remind me every hour and a half.")["reminder"] == "90"


def test_hours_to_the_listed_minutes() -> None:
    """ "a two-hour reminder": the list counts minutes, so two hours is its 120."""
    assert _goal(BOTTLE, "A two-hour reminder and the glow on.") == {
        "reminder": "120",
        "glow": "on",
    }


def test_a_possessive_length() -> None:
    """ "an hour's sleep timer": the possessive is the length of the sleep timer."""
    assert _goal(FAN, "Speed two with an hour's sleep timer.") == {"speed": 2, "sleep": "60"}


def test_switching_off_after_a_while_is_the_sleep_list() -> None:
    assert _goal(FAN, "Turn itself off after half an hour.")["sleep"] == "30"


DOORBELL = """
appliance: {id: bell_1, category: doorbell, name: "Ringwise D3 video doorbell", brand: R}
controls:
  - {id: vol_key, kind: button, label: "VOL"}
  - {id: pir_key, kind: button, label: "PIR"}
variables:
  volume: {type: numeric, ranges: [[1, 6, 1]], initial: 3, show: "V{value}"}
  motion: {type: discrete, values: ["off", low, high], label: "MOTION SENSITIVITY"}
actions:
  press_vol: {control: vol_key}
  press_pir: {control: pir_key}
features:
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
  motion:
    - {actions: [press_pir], variable: motion, effect: next}
"""

WINE_COOLER = """
appliance: {id: wine_1, category: wine_cooler, name: "Cellarto W8 wine cooler", brand: C}
controls:
  - {id: set_key, kind: button, label: "SET"}
  - {id: fan_key, kind: button, label: "FAN"}
variables:
  low_alarm: {type: numeric, unit: "°C", ranges: [[2, 10, 1]], initial: 5, label: "LOW ALARM"}
  high_alarm: {type: numeric, unit: "°C", ranges: [[8, 20, 1]], initial: 18, label: "HIGH ALARM"}
  fan: {type: discrete, values: [low, high]}
actions:
  press_set: {control: set_key}
  press_fan: {control: fan_key}
features:
  low_alarm:
    - {actions: [press_set], variable: low_alarm, effect: next}
  fan:
    - {actions: [press_fan], variable: fan, effect: next}
"""


def test_a_degree_word_before_another_setting_grades_it() -> None:
    """ "full volume": the volume's top, not the HIGH of a motion sensitivity ("full" ~ high)."""
    assert _goal(DOORBELL, "Ring at full volume.") == {"volume": 6}
    assert _goal(DOORBELL, "The quietest volume, please.") == {"volume": 1}


def test_a_degree_word_of_its_own_setting_still_names_the_value() -> None:
    assert _goal(DOORBELL, "Motion sensitivity high and volume two.") == {
        "motion": "high",
        "volume": 2,
    }


def test_as_low_as_it_goes_said_of_the_setting_before_it() -> None:
    """ "the alarm as low as it goes": the alarm's lowest, not the fan's LOW."""
    assert _goal(WINE_COOLER, "Set the alarm as low as it goes.") == {"low_alarm": 2}


def test_an_alert_is_an_alarm() -> None:
    """ "a high alert": the high alarm, not the fan's HIGH."""
    assert _goal(WINE_COOLER, "A high alert at 16 degrees.") == {"high_alarm": 16}


DESK_LAMP = """
appliance: {id: lamp_1, category: desk_lamp, name: "Lumora K4 desk lamp", brand: L}
controls:
  - {id: k_key, kind: button, label: "CCT"}
  - {id: dim_key, kind: button, label: "DIM"}
variables:
  white: {type: discrete, values: ["3000", "4000", "5500", "6000"], label: "COLOUR TEMP"}
  level: {type: numeric, unit: "%", ranges: [[20, 100, 20]], initial: 100, label: "DIM LEVEL"}
actions:
  press_k: {control: k_key}
  press_dim: {control: dim_key}
features:
  white:
    - {actions: [press_k], variable: white, effect: next}
  level:
    - {actions: [press_dim], variable: level, effect: next}
"""

HUMIDIFIER = """
appliance: {id: hum_1, category: humidifier, name: "Mistral H2 humidifier", brand: M}
controls:
  - {id: mist_key, kind: button, label: "MIST"}
  - {id: sens_key, kind: button, label: "SENS"}
variables:
  mist: {type: numeric, ranges: [[1, 4, 1]], initial: 2, show: "M{value}"}
  sensitivity: {type: discrete, values: ["1", "2", "3", "4"], show: "S{value}"}
actions:
  press_mist: {control: mist_key}
  press_sens: {control: sens_key}
features:
  mist:
    - {actions: [press_mist], variable: mist, effect: next}
  sensitivity:
    - {actions: [press_sens], variable: sensitivity, effect: next}
"""

HUMIDIFIER_MANUAL = """
Auto-humidity (SENS)
Press SENS to step through the four levels.
"""


def test_colour_temperature_words_name_kelvin() -> None:
    """Warm white is the lowest kelvin, daylight the highest, neutral about 4000 K."""
    assert _goal(DESK_LAMP, "The warmest white at 60 percent.") == {"white": "3000", "level": 60}
    assert _goal(DESK_LAMP, "Cool daylight, please.") == {"white": "6000"}
    assert _goal(DESK_LAMP, "Neutral white.") == {"white": "4000"}


def test_the_dimmest_is_the_lowest_of_the_setting_with_dim_in_its_words() -> None:
    assert _goal(DESK_LAMP, "Make it the dimmest, in neutral white.") == {
        "white": "4000",
        "level": 20,
    }
    assert _goal(DESK_LAMP, "The coolest white on the dimmest setting.") == {
        "white": "6000",
        "level": 20,
    }


def test_most_with_the_adjective_of_a_settings_noun() -> None:
    """ "the most sensitive": the top of SENSITIVITY (adjective and noun share a stem)."""
    assert _goal(HUMIDIFIER, "Mist two and the most sensitive setting.") == {
        "mist": 2,
        "sensitivity": "4",
    }


def test_a_heading_name_before_the_key_in_brackets() -> None:
    """A manual's heading "Auto-humidity (SENS)" gives the SENS setting the words auto, humidity."""
    model = loads_model(HUMIDIFIER, check=False)
    goal = parse_instruction(model, "Auto-humidity at level three.", HUMIDIFIER_MANUAL)
    assert goal == {"sensitivity": "3"}


SPEAKER = """
appliance: {id: spk_1, category: bedside_speaker, name: "Somna S1 sleep speaker", brand: S}
controls:
  - {id: vol_key, kind: button, label: "VOL"}
  - {id: track_key, kind: button, label: "TRACK"}
  - {id: chime_key, kind: button, label: "CHIME"}
variables:
  volume:
    type: discrete
    values: ["off", "1", "2", "3", "4", "5", "6"]
    show: {"off": "", "1": "V1", "2": "V2", "3": "V3", "4": "V4", "5": "V5", "6": "V6"}
  track: {type: discrete, values: ["off", T1, T2, T3, T4]}
  glow: {type: numeric, unit: "%", ranges: [[10, 100, 10]], initial: 100, label: BRIGHTNESS}
  chime: {type: discrete, values: ["off", "on"], initial: "on", label: "HOUR CHIME"}
actions:
  press_vol: {control: vol_key}
  press_track: {control: track_key}
  press_chime: {control: chime_key}
features:
  volume:
    - {actions: [press_vol], variable: volume, effect: next}
  track:
    - {actions: [press_track], variable: track, effect: next}
  chime:
    - {actions: [press_chime], variable: chime, effect: toggle}
"""


def test_an_ordinal_names_a_numbered_value_beside_an_off() -> None:
    """ "the third track" of OFF, T1 … T4: T3 (the OFF is no numbered value)."""
    assert _goal(SPEAKER, "Play the third track.") == {"track": "T3"}


def test_a_sound_with_its_own_switch_is_no_mute() -> None:
    """ "the hour chime off": the CHIME switch, not the volume to OFF."""
    assert _goal(SPEAKER, "Turn the hour chime beep off.") == {"chime": "off"}


def test_half_and_halfway_are_the_middle() -> None:
    assert _goal(SPEAKER, "Volume halfway.") == {"volume": "3"}
    assert _goal(SPEAKER, "Half brightness.") == {"glow": 50}


def test_turned_right_down_is_the_lowest_working_level() -> None:
    assert _goal(SPEAKER, "Track two with the volume turned right down.") == {
        "track": "T2",
        "volume": "1",
    }


def test_an_end_with_nothing_named_moves_what_the_display_shows() -> None:
    """ "all the way up" with no setting named: the one the idle display shows (the speed)."""
    lathe = LATHE + 'display: {idle: "{speed}"}\n'
    assert _goal(lathe, "Take it all the way up.") == {"speed": 250}


# --- fixg16: the rules above narrowed where they misfired on ordinary sentences ---


def test_all_the_way_up_after_a_named_setting() -> None:
    """ "the volume all the way up": the setting named before "all the way" is in reach."""
    assert _goal(SPEAKER, "Turn the volume all the way up.") == {"volume": "6"}
    assert _goal(LATHE, "Speed all the way up.") == {"speed": 250}


def test_an_end_not_wanted_is_no_end() -> None:
    lathe = LATHE + 'display: {idle: "{speed}"}\n'
    assert "speed" not in _goal(lathe, "Don't turn it all the way up.")


def test_an_end_said_of_another_thing_leaves_the_display_alone() -> None:
    """The idle display's setting is moved only for "it" or nothing named, not for a pedal or a
    water tray pushed or filled to its end."""
    lathe = LATHE + 'display: {idle: "{speed}"}\n'
    assert "speed" not in _goal(lathe, "Press the pedal all the way down and run it.")
    assert "speed" not in _goal(lathe, "Fill the water tray right up, then run it.")
    assert _goal(lathe, "All the way down, please.") == {"speed": 20}


CEILING_FAN = """
appliance: {id: cf_1, category: ceiling_fan, name: "Aerolux C6 ceiling fan", brand: A}
controls:
  - {id: s_key, kind: button, label: "SPEED"}
  - {id: w_key, kind: button, label: "CCT"}
variables:
  speed: {type: numeric, ranges: [[1, 6, 1]], initial: 3}
  white: {type: discrete, values: ["3000", "4000", "5000"], label: "COLOUR TEMP"}
actions:
  press_s: {control: s_key}
  press_w: {control: w_key}
features:
  speed:
    - {actions: [press_s], variable: speed, effect: next}
  white:
    - {actions: [press_w], variable: white, effect: next}
"""


def test_warm_and_cool_of_the_room_are_no_colour() -> None:
    """ "to cool the room", "it's warm in here": the weather, not the light's white."""
    assert _goal(CEILING_FAN, "Speed 5 to cool the room down.") == {"speed": 5}
    assert _goal(CEILING_FAN, "It's warm in here, speed 6.") == {"speed": 6}


def test_warm_beside_a_light_word_is_still_a_colour() -> None:
    assert _goal(CEILING_FAN, "Speed 2 and a warm light.") == {"speed": 2, "white": "3000"}


def test_a_sentence_ending_on_a_key_is_no_heading() -> None:
    """ "Then press (SENS)": a step of a procedure, not a heading naming SENS's setting."""
    from apbot.read.goal_legends import setting_words

    manual = "Mist level\nSet the mist level and then press (SENS)\nAuto humidity (SENS)\n"
    assert setting_words(manual, {"sensitivity": ["SENS"]}) == {"sensitivity": {"auto", "humidity"}}


def test_a_superlative_of_a_word_ending_in_a_double_letter() -> None:
    """ "smallest" is small + est (its own double l), "dimmest" dim + m + est: both tried."""
    from apbot.read.goal_degree_stems import superlative_stem_setting
    from apbot.read.goal_text import Text

    candidates = {"load": {"small": 1.0}, "glow": {"dim": 1.0}}
    assert superlative_stem_setting(Text.of("the smallest one"), 1, candidates) == "load"
    assert superlative_stem_setting(Text.of("the dimmest one"), 1, candidates) == "glow"


def test_a_denied_setting_is_not_put_halfway() -> None:
    """ "don't put the volume halfway": the negation before the setting's name denies it."""
    assert "volume" not in _goal(SPEAKER, "Don't put the volume halfway.")
    assert _goal(SPEAKER, "Put the volume halfway.") == {"volume": "3"}
