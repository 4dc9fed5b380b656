"""A setting whose values are a numeric scale with a code past its end (a grill's 1..6 then
T for turbo) is read from the display as strictly as a plain numeric scale: a number or a
code of its own shape after its label, never the words of another screen that begins with
the same label."""

from __future__ import annotations

from apbot.agent.reader import DisplayReader
from tests.helpers import model_from

GRILL = """
controls: [{id: power}, {id: grill}, {id: up}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  heat: {type: discrete, values: ["1", "2", "3", "4", "5", "6", "T"], wrap: false, label: GRILL}
  grill_timer: {type: time, ranges: [["00:00:00", "00:30:00", 60]], format: "h:mm",
                label: GRILL}
actions:
  press_power: {control: power}
  press_grill: {control: grill}
  hold_grill: {control: grill, skill: hold, seconds: 2}
  press_up: {control: up}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_heat: [{actions: [press_grill, press_up], variable: heat, effect: next}]
  set_grill_timer: [{actions: [hold_grill, press_up], variable: grill_timer, effect: next}]
display:
  idle: ""
"""


def readings(text: str) -> list[tuple[str | None, dict[str, object], dict[str, object]]]:
    reader = DisplayReader(model_from(GRILL))
    return [(h.screen.variable, h.values, h.outside) for h in reader.read(text).hypotheses]


def test_numbers_and_the_code_are_read() -> None:
    assert ("heat", {"heat": "4"}, {}) in readings("GRILL 4")
    assert ("heat", {"heat": "T"}, {}) in readings("GRILL T")


def test_a_value_of_the_scale_s_shape_the_belief_lacks_is_outside() -> None:
    assert ("heat", {}, {"heat": "9"}) in readings("GRILL 9")
    assert ("heat", {}, {"heat": "P"}) in readings("GRILL P")


def test_another_screen_after_the_same_label_is_no_value_of_the_scale() -> None:
    """``GRILL TIMER 5 min`` is the timer's screen printed in words the belief does not know;
    read as the heat it would make ``TIMER 5 min`` a heat and hide the timer being set."""
    assert not [r for r in readings("GRILL TIMER 5 min") if r[0] == "heat"]
    assert not [r for r in readings("GRILL timer 12") if r[0] == "heat"]
