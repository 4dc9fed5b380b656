"""Sentences in the twenty-eighth set's shapes, said of small models written for these tests: a
numbered setting named by the quantity its chart gives each number, fraction values said as
"six-eight" or by the manual's dotted names, a distance from where a setting starts, a part of
its top, the last of a numbered list, a chart's capital title, a legend that starts and stops a
thing, a word that is both a value and a switch's name, a mode's cut word said in full, "stop
<setting>", "as bright as it goes", counts per day, a scoreboard's HOME / GUEST, a game's
quarter, a clock's minutes and seconds."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction

SPRINKLER = """
appliance: {id: sprinkler_1, category: sprinkler, name: "Arc 4 sprinkler", brand: S}
controls:
  - {id: rate_key, kind: button, label: "RATE"}
  - {id: beat_key, kind: button, label: "BEAT"}
  - {id: up, kind: button, label: "+"}
  - {id: down, kind: button, label: "-"}
variables:
  rate: {type: numeric, ranges: [[1, 4, 1]], initial: 4}
  pattern: {type: numeric, ranges: [[1, 6, 1]], label: "PATTERN"}
  beat:
    type: discrete
    values: ["2/4", "3/4", "4/4", "6/8"]
    initial: "4/4"
  volume: {type: numeric, ranges: [[0, 20, 1]], initial: 8, label: "VOLUME"}
  gain: {type: numeric, ranges: [[0, 50, 5]], initial: 20, label: "GAIN"}
  speed: {type: numeric, ranges: [[0, 40, 1]], label: "SPEED"}
  backlight: {type: numeric, ranges: [[1, 4, 1]], initial: 2}
actions:
  press_rate: {control: rate_key}
  press_beat: {control: beat_key}
  press_up: {control: up}
  press_down: {control: down}
features:
  rate:
    - {actions: [press_rate], variable: rate, effect: next}
  beat:
    - {actions: [press_beat], variable: beat, effect: next}
  volume:
    - actions: [press_up, press_down]
      variable: volume
      effect: {press_up: next, press_down: prev}
"""

SPRINKLER_MANUAL = """
PATTERN LIST

   No.  Name        Spray
   ---  ----------  ------------------------
    1   MIST        fine spray
    2   JET         one long jet
    3   FAN         a flat fan
    4   SHOWER      wide drops

TURNING RATES

   The head turns at one of four rates:

     Rate key   Turn speed           For
     --------   -----------------    ---------------------
        1       2° per second        soaking a small bed
        2       5° per second        lawns
        3       10° per second       large lawns
        4       20° per second       quick rinse

BEAT

   The pulse of the head.  Common names:  3/4 waltz  ·  4/4 steady  ·  6/8 rolling
"""


def _sprinkler(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(SPRINKLER, check=False), sentence, SPRINKLER_MANUAL)


def test_a_quantity_from_the_chart_names_its_number() -> None:
    assert _sprinkler("Turn at ten degrees a second")["rate"] == 3
    assert _sprinkler("turn the head at two degrees per second")["rate"] == 1


def test_fraction_values_said_in_words_and_by_their_manual_names() -> None:
    goal = _sprinkler("A six-eight beat, please")
    assert goal["beat"] == "6/8"
    assert "pattern" not in goal  # "six" is no pattern 6
    assert _sprinkler("Waltz time")["beat"] == "3/4"


def test_a_distance_from_where_it_starts() -> None:
    assert _sprinkler("the volume three steps above where it starts")["volume"] == 11
    assert _sprinkler("raise the gain two steps from where it starts")["gain"] == 30
    assert _sprinkler("the backlight one step dimmer than it comes")["backlight"] == 1


def test_a_part_of_the_top() -> None:
    assert _sprinkler("a quarter of full speed")["speed"] == 10
    assert _sprinkler("three-quarters speed")["speed"] == 30


def test_a_chart_title_names_its_numbers_and_the_last_of_them() -> None:
    assert _sprinkler("the shower pattern")["pattern"] == 4
    assert _sprinkler("the last pattern")["pattern"] == 6


def test_as_bright_and_as_dim_as_it_goes() -> None:
    assert _sprinkler("the backlight as bright as it goes")["backlight"] == 4
    assert _sprinkler("make the backlight as dim as possible")["backlight"] == 1


DETECTOR = """
appliance: {id: detector_1, category: metal_detector, name: "Finder 8", brand: F}
controls:
  - {id: power_key, kind: button, label: "POWER"}
  - {id: mode_key, kind: button, label: "MODE"}
  - {id: tone_key, kind: button, label: "TONE"}
  - {id: click_key, kind: button, label: "CLICK"}
  - {id: sound_key, kind: button, label: "SOUND"}
  - {id: track_key, kind: button, label: "TRACK"}
variables:
  power: {type: discrete, values: ["off", "on"]}
  mode: {type: discrete, values: [all, disc], show: {all: "ALL", disc: "DISC"}}
  discrimination: {type: numeric, ranges: [[0, 40, 5]], label: "DISC LV"}
  sensitivity:
    type: discrete
    values: ["1", "2", "3", "4"]
    initial: "3"
    show: {"1": "SENS ▮▯▯▯", "2": "SENS ▮▮▯▯", "3": "SENS ▮▮▮▯", "4": "SENS ▮▮▮▮"}
  tones: {type: discrete, values: ["1", "2", "4"]}
  click: {type: discrete, values: ["off", "on"]}
  sound: {type: discrete, values: [click, beep, wood]}
  tracking: {type: discrete, values: [slow, fast, "off"]}
actions:
  press_power: {control: power_key}
  press_mode: {control: mode_key}
  press_tone: {control: tone_key}
  press_click: {control: click_key}
  press_sound: {control: sound_key}
  press_track: {control: track_key}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  mode:
    - {actions: [press_mode], variable: mode, effect: next}
  tones:
    - {actions: [press_tone], variable: tones, effect: next}
  click:
    - {actions: [press_click], variable: click, effect: toggle}
  sound:
    - {actions: [press_sound], variable: sound, effect: next}
  tracking:
    - {actions: [press_track], variable: tracking, effect: next}
"""

DETECTOR_MANUAL = """
KEYS

  1  POWER — switches the detector on and off.
  2  CLICK — starts and stops the pinpointer.
  3  SOUND — chooses the sound of the click.
"""


def _detector(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(DETECTOR, check=False), sentence, DETECTOR_MANUAL)


def test_a_legend_that_starts_and_stops_a_thing_names_the_switch() -> None:
    assert _detector("pinpointer on")["click"] == "on"


def test_a_value_word_that_is_a_switchs_name() -> None:
    goal = _detector("the wood as the click sound")
    assert goal["sound"] == "wood"
    assert "click" not in goal
    goal = _detector("start the click")
    assert goal["click"] == "on"
    assert "sound" not in goal and "power" not in goal


def test_a_modes_cut_word_said_in_full() -> None:
    assert _detector("Discrimination mode at thirty-five") == {
        "mode": "disc",
        "discrimination": 35,
    }


def test_stop_a_setting_is_its_off() -> None:
    assert _detector("stop tracking altogether")["tracking"] == "off"


SCOREBOARD = """
appliance: {id: board_1, category: scoreboard, name: "Court 2 scoreboard", brand: C}
controls:
  - {id: home_key, kind: button, label: "HOME +"}
  - {id: guest_key, kind: button, label: "GUEST +"}
  - {id: poss_key, kind: button, label: "POSS"}
  - {id: per_key, kind: button, label: "PER"}
  - {id: clock_key, kind: button, label: "CLOCK"}
variables:
  home_score: {type: numeric, ranges: [[0, 99, 1]], label: "HOME"}
  guest_score: {type: numeric, ranges: [[0, 99, 1]], label: "GUEST"}
  possession: {type: discrete, values: [none, home, guest]}
  period:
    type: discrete
    values: ["1", "2", "3", "4", OT]
    show: {"1": "PER 1", "2": "PER 2", "3": "PER 3", "4": "PER 4", OT: "PER OT"}
  game_clock:
    type: time
    ranges: [["00:00:00", "00:20:00", 1]]
    initial: "00:10:00"
    format: "mm:ss"
    label: "CLOCK"
  portions: {type: numeric, ranges: [[1, 4, 1]], label: "PORTIONS"}
actions:
  press_home: {control: home_key}
  press_guest: {control: guest_key}
  press_poss: {control: poss_key}
  press_per: {control: per_key}
  press_clock: {control: clock_key}
features:
  home_score:
    - {actions: [press_home], variable: home_score, effect: next}
  guest_score:
    - {actions: [press_guest], variable: guest_score, effect: next}
  possession:
    - {actions: [press_poss], variable: possession, effect: next}
  period:
    - {actions: [press_per], variable: period, effect: next}
  game_clock:
    - {actions: [press_clock], variable: game_clock, effect: prev}
"""


def _board(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(SCOREBOARD, check=False), sentence)


def test_home_and_guests_said_as_whose_score() -> None:
    assert _board("Home twelve, guests eighteen") == {"home_score": 12, "guest_score": 18}
    assert (
        _board("The guests lead six to four, and possession to the home side")["possession"]
        == "home"
    )


def test_a_games_quarter_and_overtime() -> None:
    assert _board("the third quarter")["period"] == "3"
    assert _board("we are in overtime")["period"] == "OT"


def test_minutes_and_seconds_said_as_a_clock_reads_them() -> None:
    goal = _board("three minutes twenty on the clock")
    assert goal["game_clock"] == "00:03:20"
    assert "home_score" not in goal and "guest_score" not in goal


def test_a_count_per_day_is_no_length_of_time() -> None:
    assert "game_clock" not in _board("two portions a day")
    assert "game_clock" not in _board("a portion twice a day")
