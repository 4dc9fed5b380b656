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
