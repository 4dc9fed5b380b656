"""Rules of the set24 session, each on a small manual of our own words: turns named with no verb
(``actions._TURN_WAY``), kelvin as a unit (``values.UNIT``), an aside between a range's "from" and
its "to" (``values._FROM_ASIDE_RE``), a click equated with its amount
(``value_steps._CLICK_EQUALS_RE``), a specification table's next row is another thing's
(``evidence_context._next_row_named``), "hold it again" holds the same key
(``roles_holds._HOLD_IT``), examples that start from the factory settings say nothing of how it
is delivered (``roles_fixed._EXAMPLES_FROM_RE``) and a state chart's arrows labelled with the key
(``value_list_shapes._ARROW``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.actions import parse_actions
from apbot.read.shown_bars import _counted, _levels
from apbot.read.value_steps import find_step
from apbot.read.values import find_ranges

# a desk lamp with two endless knobs and a power key held to switch
LAMP = """
Lumetto DL-9 desk lamp

 SPECIFICATIONS

 | Item              | DL-9         | DL-9 Pro      |
 |-------------------|--------------|---------------|
 | White tone        | 2700 – 6000 K| 2200 – 6500 K |
 | Tone step         | 100 K        | 50 K          |
 | Dimming           | 0 – 100 %    | 0 – 100 %     |

 CONTROLS

  ①  ⏻ key (hold)
  ②  DIM knob – turn to dim or brighten
  ③  TONE knob – turn to set how warm the white is

 SWITCHING

 Hold ⏻ for 3 seconds to switch on; hold it again for 3 seconds to switch off.

 DIMMING

 Turn DIM clockwise for more light, anticlockwise for less, from 0 % to 100 %.

   Small steps    each click = 2 %

 TONE

 Each click of TONE changes the white by 100 K, from 2700 K (cosy, like an old bulb) to
 6000 K (crisp, like noon sun). It stops at both ends.

 EXAMPLES (starting from the factory settings, lamp switched on)

   Reading light: TONE clockwise ten times.
"""
LAMP_ACTIONS = ["hold_power", "dim_cw", "dim_ccw", "tone_cw", "tone_ccw"]


def test_a_turn_named_with_no_verb_is_a_turn() -> None:
    infos = {i.name: i for i in parse_actions(["volume_cw", "volume_ccw", "fan_counter_clockwise"])}
    assert (infos["volume_cw"].skill, infos["volume_cw"].controls) == ("turn_cw", ("volume",))
    assert infos["volume_ccw"].skill == "turn_ccw"
    assert infos["fan_counter_clockwise"].skill == "turn_ccw"
    # up / down / left / right name keys as often as turns: still presses
    assert parse_actions(["volume_up"])[0].skill == "press"


def test_kelvin_and_a_long_aside_between_from_and_to_make_a_range() -> None:
    [found] = find_ranges("it goes from 3000 K (soft, like a candle or an old bulb) to 5000 K")
    assert (found.low, found.high, found.unit) == (3000, 5000, "K")


def test_a_click_equated_with_its_amount_is_the_step() -> None:
    assert find_step("Fine mode   each click = 5 %") == (5, "%")
    assert find_step("one press: 10 °C") == (10, "°C")


def test_a_knob_whose_range_is_in_kelvin_reads_its_own_sentence_not_the_next_table_row() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    tone = model.variables["tone"]
    assert tone.type == "numeric" and tone.unit == "K"
    assert [list(r) for r in tone.ranges] == [[2700, 6000, 100]]
    dim = model.variables["dim"]
    assert [list(r) for r in dim.ranges] == [[0, 100, 2]]


def test_hold_it_again_to_switch_off_makes_the_held_key_the_power() -> None:
    model = read_manual(LAMP, LAMP_ACTIONS).model
    assert "power" in model.variables
    assert model.features["power"][0].actions == ["hold_power"]
    # the examples start switched on: the lamp is not delivered switched on
    assert model.variables["power"].initial != "on"


FOGGER = """
Nebula F-3 fogger

 MODES

 The MODE key steps through the modes in this order:

      HAND  ──MODE──►  AUTO  ──MODE──►  REMOTE  ──MODE──►  HAND …

 The lamp of the chosen mode is lit.
"""


def test_a_state_chart_with_the_key_on_its_arrows_lists_the_values() -> None:
    model = read_manual(FOGGER, ["press_mode"]).model
    assert model.variables["mode"].values == ["hand", "auto", "remote"]


# a clock whose keys are lettered in small letters, the arrows shared by two keys that open
# them, and a key printed with the first of the units it cycles
CLOCK = """
Tempora RC-2 radio clock

 KEYS

   (a) °C/°F   changes the temperature unit
   (b) hPa     steps the air-pressure unit
   (c) SHIFT   opens the time shift
   (d) HI      opens the heat warning limit
   (e)(f) ▲ ▼  change the value that is open

 Note: ▲ and ▼ only work after SHIFT or HI has been pressed. On their own they do nothing.

 TEMPERATURE UNIT (°C / °F)

 Press °C/°F to change between Celsius and Fahrenheit.

 BAROMETER

 Each press of hPa moves to the next unit:

      hPa  →  inHg  →  mmHg  →  hPa …

 TIME SHIFT

  1. Press SHIFT.
  2. Press ▲ or ▼, from −2 to +2 h. It stops at both ends.

 HEAT WARNING

  1. Press HI.
  2. Press ▲ or ▼ to change it by 1 degree, from 25 to 40 °C.
"""
CLOCK_ACTIONS = [
    "press_unit",
    "press_pressure",
    "press_shift",
    "press_hi",
    "press_up",
    "press_down",
]


def test_small_lettered_legend_lines_name_keys_and_a_cycle_comes_round_to_the_key() -> None:
    model = read_manual(CLOCK, CLOCK_ACTIONS).model
    pressure = next(v for v in model.variables.values() if v.label == "hPa")
    assert pressure.values == ["hpa", "inhg", "mmhg"]


def test_a_pair_that_only_works_after_other_keys_serves_them_both() -> None:
    model = read_manual(CLOCK, CLOCK_ACTIONS).model
    data = model.model_dump(mode="json")
    opened = {
        steps[0]["actions"][0]: steps[1]["variable"]
        for steps in data["features"].values()
        if len(steps) == 2 and set(steps[1]["actions"]) == {"press_up", "press_down"}
    }
    assert set(opened) == {"press_shift", "press_hi"}, data["features"]


# a brush whose hold switches a timer shown by a sign, and whose level bar counts lamps
BRUSH = """
Purelle FB-2 face brush

 PANEL

   ①  bar: six lights; the number of lit lights is the level
   ②  ⧗ lit = pause timer on

 Press ⏻ to switch on or off.

 MODES

 Press MODE to go to the next mode:

      SOFT  →  DEEP  →  SOFT …

 LEVEL

 Press + for a stronger and − for a gentler pulse. Every mode has its own number of
 levels, and every mode keeps its own level:

 | mode | levels available | level at delivery |
 |------|------------------|-------------------|
 | SOFT | 1 – 4            | 2                 |
 | DEEP | 1 – 6            | 3                 |

   ▮ ▯ ▯ ▯ ▯ ▯   level 1   the gentlest
   ▮ ▮ ▮ ▯ ▯ ▯   level 3
   ▮ ▮ ▮ ▮ ▮ ▮   level 6   DEEP only

 PAUSE TIMER

   Hold MODE for 2 seconds  →  the pause timer changes between on and off.
"""
BRUSH_ACTIONS = ["press_power", "press_mode", "hold_mode", "press_plus", "press_minus"]


def test_a_hold_that_changes_a_timer_between_on_and_off_is_a_toggle_shown_by_its_sign() -> None:
    model = read_manual(BRUSH, BRUSH_ACTIONS).model
    timer = model.variables["pause_timer"]
    assert timer.values == ["off", "on"]
    assert timer.show == {"off": "", "on": "⧗"}
    assert model.variables["mode"].values == ["soft", "deep"]


def test_a_bar_that_counts_its_level_shows_every_level_of_every_mode() -> None:
    printed = {"1": "▮▯▯▯▯▯", "3": "▮▮▮▯▯▯", "6": "▮▮▮▮▮▮"}
    levels = ["1", "2", "3", "4", "5", "6"]
    bars = _counted(printed, levels)
    assert bars["2"] == "▮▮▯▯▯▯" and bars["5"] == "▮▮▮▮▮▯"
    assert _counted({"1": "▮▯▯", "2": "▯▮▯", "3": "▯▯▮"}, ["1", "2", "3", "4"]) == {
        "1": "▮▯▯",
        "2": "▯▮▯",
        "3": "▯▯▮",
    }  # (a moving lamp counts nothing)
    cased = {
        "type": "numeric",
        "cases": {"soft": {"ranges": [[1, 4, 1]]}, "deep": {"ranges": [[1, 6, 1]]}},
    }
    assert _levels(cased) == levels
