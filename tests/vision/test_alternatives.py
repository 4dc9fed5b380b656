"""The perception hook: of a photo's possible texts, the cheapest readable one."""

from __future__ import annotations

from dataclasses import dataclass

from apbot.agent.environment import Feedback
from apbot.agent.perception import Perceiver
from apbot.examples import load_example


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
