"""The perception hook: of a photo's possible texts, the cheapest readable one."""

from __future__ import annotations

from dataclasses import dataclass

from apbot.agent.environment import Feedback
from apbot.agent.perception import Perceiver
from apbot.examples import load_example
from tests.helpers import suite_model


@dataclass
class _Reading:
    alternatives: list[tuple[str, float]]


def test_look_alikes_are_settled_by_the_display_rules() -> None:
    perceiver = Perceiver(load_example("microwave_keypad"))
    # "P" read as a look-alike first; only "PL7" fits the belief's screens
    feedback = Feedback("PI7", image=_Reading([("PI7", 0.0), ("PL7", 0.0)]))
    assert perceiver.perceive(feedback, {}).values == {"power_level": 7}


def test_a_cheaper_reading_wins_over_the_prediction() -> None:
    perceiver = Perceiver(load_example("microwave_keypad"))
    feedback = Feedback("PL8", image=_Reading([("PL8", 0.0), ("PL7", 2.0)]))
    seen = perceiver.perceive(feedback, {"power_level": 7}, ("focus", "power_level"))
    assert seen.values == {"power_level": 8}


def test_a_look_alike_read_only_in_part_loses_to_one_read_whole() -> None:
    """Seven segments light the same bars for O and D: 'DFF 2 h' leaves the off-timer unread
    and so differs less from a prediction of no timer, yet 'OFF 2 h' is the one the display
    rules explain whole, and the one to believe."""
    perceiver = Perceiver(suite_model("air_conditioner_1"))
    shown = "OFF 2 h  RUN  LIGHT OFF"
    tied = [("DFF 2 h  RUN  LIGHT OFF", 0.0), (shown, 0.0)]
    prediction = {"power": "on", "timer_off": "00:00:00", "light": "off"}
    seen = perceiver.perceive(Feedback(tied[0][0], image=_Reading(tied)), prediction)
    assert not seen.partial
    assert seen.values["timer_off"] == "02:00:00"


def test_an_arrow_drawn_small_is_the_run_lamp_the_belief_prints_large() -> None:
    """A status row's small ▸ is the ▶ the toaster's run lamp prints: read as leftover text,
    the part read would say the oven is off."""
    perceiver = Perceiver(suite_model("toaster_oven_3"))
    photo = [("TIME 0:28  ▸", 0.0)]
    seen = perceiver.perceive(Feedback(photo[0][0], image=_Reading(photo)), {"running": "on"})
    assert seen.values["running"] == "on" and not seen.partial


def test_a_whole_reading_does_not_beat_a_much_cheaper_one() -> None:
    """Only look-alikes trade: a reading far dearer than the photo's best is no look-alike."""
    perceiver = Perceiver(load_example("microwave_keypad"))
    feedback = Feedback("PL8", image=_Reading([("PL8", 0.0), ("PL7", 5.0)]))
    assert perceiver.perceive(feedback, {"power_level": 7}).values == {"power_level": 8}
