"""Faults in a variable's values: each kind gives a valid model that differs as it says."""

from __future__ import annotations

import random

from apbot.bench.faults import (
    effect_direction,
    first_valid,
    missing_case,
    step_size,
    value_order,
)
from apbot.model.domain import all_values
from tests.bench.faults.models import errors, every_candidate, oven, shown, value
from tests.helpers import model_from

TIMER = """
controls:
  - {id: timer_button, label: TIMER}
  - {id: up_button, label: "▲"}
  - {id: down_button, label: "▼"}
variables:
  delay: {type: numeric, unit: h, ranges: [[0, 12, 2]], initial: 4}
actions:
  press_timer: {control: timer_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
features:
  set_delay:
    - {actions: [press_timer]}
    - actions: [press_up, press_down]
      variable: delay
      effect: {press_up: next, press_down: prev}
"""


def test_effect_direction_makes_up_go_down() -> None:
    found = first_valid(effect_direction(model_from(TIMER), "delay", random.Random(0)))
    assert found is not None
    faulty, fault = found
    assert "press_up next → prev" in fault.detail
    assert value(faulty, ["press_timer", "press_up"], "delay") == 2


def test_step_size_keeps_the_range_aligned_and_the_initial_value() -> None:
    for seed in range(6):
        found = first_valid(step_size(model_from(TIMER), "delay", random.Random(seed)))
        assert found is not None
        faulty, fault = found
        ((start, end, step),) = faulty.variables["delay"].ranges  # type: ignore[union-attr]
        assert step in (1, 4) and (end - start) % step == 0 and end <= 12
        assert f"step 2 h → {step} h" in fault.detail
        assert value(faulty, [], "delay") == 4
        assert errors(faulty) == []


def test_step_size_never_offers_the_same_values_written_differently() -> None:
    # [150, 200, 50] then [200, 400, 5]: doubling the first step to 100 still holds 150, 200
    text = TIMER.replace(
        "[[0, 12, 2]], initial: 4", "[[150, 200, 50], [200, 400, 5]], initial: 150"
    )
    truth = model_from(text)
    candidates = every_candidate(step_size, truth, "delay", seeds=12)
    assert candidates
    for faulty, fault in candidates:
        assert set(all_values(faulty.variables["delay"])) != set(
            all_values(truth.variables["delay"])
        ), fault


def test_missing_case_leaves_the_setting_absent_for_one_programme() -> None:
    truth = oven()
    ((faulty, fault),) = every_candidate(missing_case, truth, "temperature")
    assert fault.kind == "missing_case" and "'grill'" in fault.detail  # bake is the start
    to_grill = ["press_power", "press_mode", "press_temp"]
    assert value(truth, to_grill, "temperature") == 200
    assert value(faulty, to_grill, "temperature") is None
    assert shown(faulty, to_grill) == "TEMPERATURE --"
    assert value(faulty, ["press_power", "press_temp"], "temperature") == 180  # bake is kept


def test_value_order_leaves_a_two_value_cycle_alone() -> None:
    # two values that a key cycles through come round in either order: no fault to offer
    text = TIMER.replace(
        "delay: {type: numeric, unit: h, ranges: [[0, 12, 2]], initial: 4}",
        "delay: {type: discrete, values: [low, high]}",
    ).replace(
        "effect: {press_up: next, press_down: prev}", "effect: {press_up: next, press_down: next}"
    )
    assert every_candidate(value_order, model_from(text), "delay") == []
    three = text.replace("values: [low, high]", "values: [low, mid, high]")
    assert every_candidate(value_order, model_from(three), "delay")
