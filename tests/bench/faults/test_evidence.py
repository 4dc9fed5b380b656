"""first_difference: a sequence of presses that tells a faulty model from the truth."""

from __future__ import annotations

from apbot.bench.faults.evidence import first_difference
from apbot.sim.simulator import Simulator
from tests.bench.faults.models import OVEN, oven
from tests.helpers import model_from


def _replay(model: object, actions: list[str]) -> tuple[str, bool]:
    sim = Simulator(model)  # type: ignore[arg-type]
    seen = sim.observe()
    for action in actions:
        seen = sim.step(action) if action in sim.compiled.action_index else seen
    return seen.text, seen.accepted


def test_the_same_model_shows_no_difference() -> None:
    assert first_difference(oven(), oven()) is None


def test_a_difference_in_the_display_is_found_and_replays() -> None:
    truth, faulty = oven(), model_from(OVEN.replace('show: "DL{value}"', 'show: "D{value}"'))
    found = first_difference(truth, faulty)
    assert found == ["press_power", "press_timer"]
    assert _replay(truth, found) != _replay(faulty, found)


def test_a_difference_deep_in_a_range_is_found_by_pressing_one_key_again_and_again() -> None:
    truth = oven()
    faulty = model_from(OVEN.replace("ranges: [[0, 6, 1]]", "ranges: [[0, 5, 1]]"))
    found = first_difference(truth, faulty)
    assert found is not None and found[-6:] == ["press_timer"] * 6


def test_a_difference_before_any_press_is_the_empty_sequence() -> None:
    truth = oven()
    faulty = model_from(OVEN.replace('idle: "{mode}"', 'idle: "READY"'))
    assert first_difference(truth, faulty) is None  # both dark while off: the same
    faulty = model_from(OVEN.replace(', display: "", hide: true}', ', display: "OFF", hide: true}'))
    assert first_difference(truth, faulty) == []
