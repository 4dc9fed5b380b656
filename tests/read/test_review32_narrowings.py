"""Narrowings of the goal parser's rules merged in the thirty-first session, each probed on a
small appliance written for these tests: a flow said per minute is no count of things between
which a seconds setting waits; "maximum" said of a setting whose HIGH value is no end of its
list asks for that end, not for HIGH; "half a stop" is no full stop, and a stop down said
first keeps its sign. And in the reader: a countdown that "stops at 0 and 3 beeps sound"
states no span of 0 to 3."""

from __future__ import annotations

from apbot.model.load import loads_model
from apbot.read.goal import parse_instruction
from apbot.read.goal_error import GoalParseError

PUMP = """
appliance: {id: pond_1, category: pond_pump, name: "Ripl pond pump", brand: R}
controls:
  - {id: flow_key, kind: button, label: "FLOW"}
  - {id: rest_key, kind: button, label: "REST"}
variables:
  flow: {type: discrete, values: [LOW, MID, HIGH], initial: MID, wrap: true}
  rest: {type: numeric, unit: "s", ranges: [[2, 30, 1]], initial: 10, wrap: true}
actions:
  press_flow: {control: flow_key}
  press_rest: {control: rest_key}
features:
  flow:
    - {actions: [press_flow], variable: flow, effect: next}
  rest:
    - {actions: [press_rest], variable: rest, effect: next}
"""

PUMP_MANUAL = """
FLOW sets how much water the pump moves: LOW is about 4 litres per minute, MID 8 litres per
minute and HIGH 12 litres per minute.
REST sets the seconds the fountain waits between two jets (2 to 30 seconds); jets per minute
follow from it.
"""


def _pump(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(PUMP), sentence, PUMP_MANUAL)


def _rest(sentence: str) -> object:
    """The rest the sentence is read to ask for, None for none (or for no reading)."""
    try:
        return _pump(sentence).get("rest")
    except GoalParseError:
        return None


def test_a_flow_per_minute_is_no_count_between_rests() -> None:
    assert _rest("twelve litres a minute") is None
    assert _rest("high flow, twelve litres a minute") is None


def test_the_things_counted_between_still_convert() -> None:
    assert _pump("fifteen jets a minute") == {"rest": 4}


WOK = """
appliance: {id: wok_1, category: induction_wok, name: "Wokka", brand: W}
controls:
  - {id: heat_key, kind: button, label: "HEAT"}
  - {id: fan_key, kind: button, label: "FAN"}
variables:
  heat: {type: discrete, values: [LOW HEAT, MEDIUM HEAT, HIGH HEAT, BOOST], initial: LOW HEAT}
  fan: {type: numeric, ranges: [[1, 5, 1]], initial: 1, wrap: true}
actions:
  press_heat: {control: heat_key}
  press_fan: {control: fan_key}
features:
  heat:
    - {actions: [press_heat], variable: heat, effect: next}
  fan:
    - {actions: [press_fan], variable: fan, effect: next}
"""

WOK_MANUAL = """
HEAT steps through LOW HEAT, MEDIUM HEAT, HIGH HEAT and BOOST (the hottest, for searing).
"""


def test_maximum_is_the_end_not_the_high_value() -> None:
    model = loads_model(WOK)
    assert parse_instruction(model, "maximum heat", WOK_MANUAL) == {"heat": "BOOST"}
    assert parse_instruction(model, "a little heat", WOK_MANUAL) == {"heat": "LOW HEAT"}


_THIRDS = ["-2.0", "-1.7", "-1.3", "-1.0", "-0.7", "-0.3", "0.0", "+0.3", "+0.7", "+1.0", "+1.3"]
_COMP = ", ".join(f'"{v}"' for v in _THIRDS)
FLASH = f"""
appliance: {{id: blink_1, category: speedlight, name: "Blink", brand: B}}
controls:
  - {{id: comp_key, kind: button, label: "FEC"}}
  - {{id: zoom_key, kind: button, label: "ZOOM"}}
variables:
  comp: {{type: discrete, values: [{_COMP}], initial: "0.0", wrap: true}}
  zoom: {{type: numeric, unit: " mm", ranges: [[24, 105, 1]], initial: 50, wrap: true}}
actions:
  press_comp: {{control: comp_key}}
  press_zoom: {{control: zoom_key}}
features:
  comp:
    - {{actions: [press_comp], variable: comp, effect: next}}
  zoom:
    - {{actions: [press_zoom], variable: zoom, effect: next}}
"""
FLASH_MANUAL = "FEC sets the flash compensation in thirds of a stop."


def _flash(sentence: str) -> dict[str, object]:
    return parse_instruction(loads_model(FLASH), sentence, FLASH_MANUAL)


def test_a_stop_down_said_first_stays_down() -> None:
    assert _flash("One stop down, zoom at 50 mm") == {"comp": "-1.0", "zoom": 50}
    assert _flash("zoom at 50 mm, a stop less flash") == {"comp": "-1.0", "zoom": 50}
    assert _flash("zoom at 50 mm and go a stop down") == {"comp": "-1.0", "zoom": 50}


def test_half_a_stop_is_no_full_stop() -> None:
    assert "comp" not in _flash("zoom at 50 mm, half a stop darker")


def test_a_stop_followed_by_a_count_of_beeps_is_no_span() -> None:
    from apbot.read.values_stated import stated_span

    assert stated_span("When the countdown stops at 0 and 3 beeps sound, open the lid.") is None
    assert stated_span("The timer stops at 0 and 10 seconds later the fan stops too.") is None
    assert stated_span("The depth stops at 1 and at 6; it does not wrap.") == (1, 6, "")
