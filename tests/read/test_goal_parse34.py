"""Sentences in the twenty-ninth set's shapes, said of small models written for these tests: a
heading read out digit by digit or named by a compass point, a mode's name fused with the noun
its legend says it of, a named level asked for by the quantity the manual charts for it (and by
a superlative of that quantity), and a contents page that names no coded value."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_manual import coded_names

TROLLING = """
appliance: {id: trolling_motor_1, category: trolling_motor, name: "Bowline 40 motor", brand: B}
controls:
  - {id: hold_key, kind: button, label: "HOLD"}
  - {id: free_key, kind: button, label: "FREE"}
  - {id: left, kind: button, label: "<"}
  - {id: right, kind: button, label: ">"}
  - {id: beam_key, kind: button, label: "BEAM"}
  - {id: thrust_key, kind: button, label: "THRUST"}
variables:
  mode: {type: discrete, values: [free, cruise]}
  heading: {type: numeric, unit: "°", ranges: [[0, 359, 1]], initial: 90, wrap: true}
  thrust: {type: numeric, ranges: [[1, 5, 1]], initial: 3, wrap: true}
  lamp: {type: discrete, values: [glow, trail, race], initial: glow}
actions:
  press_hold: {control: hold_key}
  press_free: {control: free_key}
  press_left: {control: left}
  press_right: {control: right}
  press_beam: {control: beam_key}
  press_thrust: {control: thrust_key}
features:
  thrust:
    - {actions: [press_thrust], variable: thrust, effect: next}
  cruise:
    - {actions: [press_hold], variable: mode, effect: {to: cruise}}
  free:
    - {actions: [press_free], variable: mode, effect: {to: free}}
  heading:
    - actions: [press_left, press_right]
      variable: heading
      effect: {press_left: {skip: -1}, press_right: {skip: 1}}
  lamp:
    - {actions: [press_beam], variable: lamp, effect: next}
"""

TROLLING_MANUAL = """
CONTENTS
  1  Fitting the motor ............................ 2
  2  The bow lamp ................................. 3

KEYS
  HOLD   CRUISE - the motor keeps the bow on the heading shown
  FREE   steer with the foot pedal

BOW LAMP
  Each press of BEAM steps GLOW -> TRAIL -> RACE.

     Step     Light      Lasts
     GLOW     60 lm      30 h
     TRAIL    350 lm     6 h
     RACE     800 lm     2 h
"""


def _motor(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(TROLLING), sentence, TROLLING_MANUAL)


def test_a_heading_read_digit_by_digit() -> None:
    assert _motor("Hold heading zero six five")["heading"] == 65
    assert _motor("heading three-two-zero, thrust four") == {"heading": 320, "thrust": 4}


def test_a_compass_point_is_its_bearing() -> None:
    assert _motor("Point her due west")["heading"] == 270
    assert _motor("Head south")["heading"] == 180


def test_a_mode_fused_with_its_legend_noun() -> None:
    assert _motor("Put it on cruisecontrol... no, on cruisemotor")["mode"] == "cruise"


def test_a_level_named_by_its_charted_quantity() -> None:
    assert _motor("lamp at three hundred and fifty lumens")["lamp"] == "trail"
    assert _motor("about eight hundred and fifty lumens")["lamp"] == "race"
    assert "lamp" not in _motor("six hundred lumens")  # no chart row, and no hedge


def test_a_superlative_of_the_charted_quantity() -> None:
    assert _motor("the brightest light")["lamp"] == "race"
    assert _motor("the dimmest light for the night")["lamp"] == "glow"


CODED = """
appliance: {id: fogger_1, category: fogger, name: "Mist 3", brand: M}
controls:
  - {id: prog_key, kind: button, label: "PROG"}
variables:
  programme: {type: numeric, ranges: [[1, 3, 1]], initial: 1}
actions:
  press_prog: {control: prog_key}
features:
  programme:
    - {actions: [press_prog], variable: programme, effect: next}
"""

CODED_MANUAL = """
CONTENTS
  1  Safety ........................................ 2
  2  Charging ...................................... 3
  3  Cleaning ...................................... 4

PROGRAMMES
  PROG steps through the three mist programmes: 1 is a fine mist, 2 a dense fog, 3 pulses.
"""


def test_a_contents_page_names_no_programme() -> None:
    names = {name for _var, _code, name in coded_names(loads_model(CODED), CODED_MANUAL)}
    assert not any(name.startswith(("Safety", "Charging")) for name in names)
    assert "programme" not in parse_instruction(loads_model(CODED), "Charging", CODED_MANUAL)


PUMP = """
appliance: {id: pond_pump_1, category: pond_pump, name: "Ripple P2", brand: R}
controls:
  - {id: prog_key, kind: button, label: "PROG"}
  - {id: flow_key, kind: button, label: "FLOW"}
variables:
  programme: {type: numeric, ranges: [[0, 12, 1]], initial: 0, wrap: true}
  flow: {type: numeric, ranges: [[1, 3, 1]], initial: 2, wrap: true}
actions:
  press_prog: {control: prog_key}
  press_flow: {control: flow_key}
features:
  programme:
    - {actions: [press_prog], variable: programme, effect: next}
  flow:
    - {actions: [press_flow], variable: flow, effect: next}
"""

PUMP_MANUAL = """
PROGRAMMES

   No.    What the pump does
    0     Always on: the pump never stops
    1     Runs for 1 hour each morning
    2     Runs for 2 hours each morning
   3-10   Runs for 3 ... 10 hours each morning
    11    Fountain show: short bursts every minute
    12    Holiday: ten minutes an hour
"""


def _pump(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(PUMP), sentence, PUMP_MANUAL)


def test_a_code_named_by_its_chart_row() -> None:
    assert _pump("Put on the fountain show")["programme"] == 11
    assert _pump("Holiday programme, flow one") == {"programme": 12, "flow": 1}
    assert _pump("run it seven hours every morning")["programme"] == 7
    assert _pump("the longest morning run")["programme"] == 10


DOSER = """
appliance: {id: doser_1, category: dosing_pump, name: "Drop 2 doser", brand: D}
controls:
  - {id: vol_key, kind: button, label: "VOL"}
  - {id: rate_key, kind: button, label: "RATE"}
  - {id: head_key, kind: button, label: "HEAD"}
variables:
  dose: {type: numeric, unit: "µL", ranges: [[100, 2000, 100]], initial: 500, wrap: true}
  rate: {type: numeric, ranges: [[1, 5, 1]], initial: 2, wrap: true}
  head: {type: discrete, values: [mist, fan, jet, stream], wrap: true}
actions:
  press_vol: {control: vol_key}
  press_rate: {control: rate_key}
  press_head: {control: head_key}
features:
  dose:
    - {actions: [press_vol], variable: dose, effect: next}
  rate:
    - {actions: [press_rate], variable: rate, effect: next}
  head:
    - {actions: [press_head], variable: head, effect: next}
"""


def _doser(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(DOSER), sentence, "")


def test_microlitres_and_millilitres_on_a_setting_in_microlitres() -> None:
    assert _doser("dose 700 µL")["dose"] == 700
    assert _doser("a dose of one and a half millilitres")["dose"] == 1500


def test_a_step_counted_from_the_start_with_the_setting_named_inside() -> None:
    assert _doser("two rate steps faster than it comes")["rate"] == 4
    assert _doser("one head down from where it starts")["head"] == "stream"
