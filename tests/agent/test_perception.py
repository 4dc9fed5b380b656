"""Perception (apbot.agent.perception): a press's own setting read by its unit where the
belief's screen for it is not found."""

from __future__ import annotations

from apbot.agent.environment import Feedback
from apbot.agent.perception import Perceiver
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from

KETTLE = """
controls: [{id: plus}, {id: volume}]
variables:
  temperature: {type: numeric, unit: "°C", ranges: [[0, 100, 5]], label: TEMPERATURE}
  volume: {type: numeric, unit: "%(volume_unit)s", ranges: [[50, 1000, 50]], label: VOLUME}
actions:
  press_plus: {control: plus}
  press_volume: {control: volume}
features:
  set_temperature: [{actions: [press_plus], variable: temperature, effect: next}]
  set_volume: [{actions: [press_volume], variable: volume, effect: next}]
"""


def kettle(volume_unit: str = "ml") -> ApplianceModel:
    return model_from(KETTLE % {"volume_unit": volume_unit})


def read(model: ApplianceModel, text: str) -> tuple[dict[str, object], dict[str, object]]:
    seen = Perceiver(model).perceive(
        Feedback(text, {}, True, ""), {"temperature": 5, "volume": 50}, ("focus", "temperature")
    )
    return seen.values, seen.outside


def test_a_number_in_the_settings_own_unit_is_its_value() -> None:
    assert read(kettle(), "55°C  LOCK RED") == ({"temperature": 55}, {})
    assert read(kettle(), "57 °C") == ({}, {"temperature": 57})  # a value the belief lacks


def test_a_unit_shared_with_another_setting_or_two_numbers_say_nothing() -> None:
    assert "temperature" not in read(kettle(volume_unit="°C"), "55°C")[0]
    assert "temperature" not in read(kettle(), "55°C 60°C")[0]
    assert "temperature" not in read(kettle(), "READY")[0]


def test_the_belief_s_own_screen_still_reads_first() -> None:
    assert read(kettle(), "TEMPERATURE 10°C") == ({"temperature": 10}, {})


DELAY = """
controls: [{id: plus}]
variables:
  delay: {type: numeric, unit: h, ranges: [[0, 12, 1]], label: TIMER}
actions:
  press_plus: {control: plus}
features:
  set_delay: [{actions: [press_plus], variable: delay, effect: next}]
"""


def test_a_setting_counted_in_hours_is_read_from_a_clock() -> None:
    model = model_from(DELAY)

    def hours(text: str) -> tuple[dict[str, object], dict[str, object]]:
        seen = Perceiver(model).perceive(
            Feedback(text, {}, True, ""), {"delay": 1}, ("focus", "delay")
        )
        return seen.values, seen.outside

    assert hours("DELAY 2:00  LOAF 2.5 lb") == ({"delay": 2}, {})
    assert hours("DELAY 0:30") == ({}, {"delay": 0.5})  # a step the belief lacks
    assert hours("DELAY 0:30  3:40") == ({}, {})  # two clocks: which one?


WITH_CLOCK = """
controls: [{id: plus}, {id: clock}]
variables:
  delay: {type: numeric, unit: h, ranges: [[0, 12, 1]], label: DELAY}
  clock: {type: time, ranges: [["00:00:00", "23:59:00", 60]], label: CLOCK}
actions:
  press_plus: {control: plus}
  press_clock: {control: clock}
features:
  set_delay: [{actions: [press_plus], variable: delay, effect: next}]
  set_clock: [{actions: [press_clock], variable: clock, effect: next}]
"""


def test_a_clock_is_no_count_of_hours_where_the_belief_shows_a_time_of_day() -> None:
    # ``12:45`` on a panel with a clock is the time of day, not a delay of 12.75 h to repair on
    seen = Perceiver(model_from(WITH_CLOCK)).perceive(
        Feedback("12:45", {}, True, ""), {"delay": 1, "clock": "12:45:00"}, ("focus", "delay")
    )
    assert "delay" not in seen.values and "delay" not in seen.outside


TWO_SCREENS = """
controls: [{id: a}, {id: b}]
variables:
  cook: {type: numeric, ranges: [[1, 9, 1]], label: TIME, show: "T {value}"}
  alarm: {type: numeric, ranges: [[1, 9, 1]], label: TIMER, show: "T {value}"}
actions:
  press_a: {control: a}
  press_b: {control: b}
features:
  set_cook: [{actions: [press_a], variable: cook, effect: next}]
  set_alarm: [{actions: [press_b], variable: alarm, effect: next}]
"""


def test_a_display_every_reading_of_which_contradicts_the_belief_doubts_them_all() -> None:
    # T 2 is the cook time or the alarm; the belief holds 5 and 7: one of them is wrong, and
    # neither may count as confirmed. Where the belief holds 2 for one of them, it is read so.
    perceiver = Perceiver(model_from(TWO_SCREENS))
    seen = perceiver.perceive(Feedback("T 2", {}, True, ""), {"cook": 5, "alarm": 7}, None)
    assert seen.doubted == {"cook", "alarm"} and not seen.values
    seen = perceiver.perceive(Feedback("T 2", {}, True, ""), {"cook": 2, "alarm": 7}, None)
    assert not seen.doubted and seen.values == {"cook": 2}
