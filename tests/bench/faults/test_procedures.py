"""Faults in procedures: each kind gives a valid model whose keys do what the fault says."""

from __future__ import annotations

import random

from apbot.bench.faults import (
    first_valid,
    merged_features,
    misplaced_action,
    missing_step,
    on_entry,
    side_effect,
)
from tests.bench.faults.models import OVEN, every_candidate, only, oven, press, shown, value
from tests.bench.faults.test_values import TIMER
from tests.helpers import model_from

ON = ["press_power"]


def test_missing_entry_step_makes_the_belief_adjust_without_the_entry_key() -> None:
    truth = model_from(TIMER)
    assert value(truth, ["press_up"], "delay") == 4  # ▲ does nothing before TIMER
    found = first_valid(missing_step(truth, "set_delay", random.Random(0)))
    assert found is not None
    faulty, fault = found
    assert fault.kind == "missing_step" and "press_timer" in fault.detail
    assert value(faulty, ["press_up"], "delay") == 6
    assert value(faulty, ["press_timer", "press_up"], "delay") == 6  # TIMER kept, as a no-op


def test_missing_step_skips_a_closing_key_that_another_feature_does_anyway() -> None:
    # START closing the delay procedure does what the `start` feature does: no fault
    text = TIMER.replace(
        "  press_down: {control: down_button}",
        "  press_down: {control: down_button}\n  press_start: {control: start_button}",
    )
    text = text.replace(
        '  - {id: down_button, label: "▼"}',
        '  - {id: down_button, label: "▼"}\n  - {id: start_button, label: START}',
    )
    text = text.replace(
        "variables:\n", 'variables:\n  running: {type: discrete, values: ["off", "on"]}\n'
    )
    text += '    - {actions: [press_start], variable: running, effect: {to: "on"}}\n'
    text += '  start:\n    - {actions: [press_start], variable: running, effect: {to: "on"}}\n'
    details = [f.detail for _, f in every_candidate(missing_step, model_from(text), "set_delay")]
    assert details and not any("press_start" in d for d in details), details


def test_on_entry_show_makes_the_first_press_only_show() -> None:
    truth = oven()
    ((faulty, fault),) = every_candidate(on_entry, truth, "set_delay")
    assert "only shows delay" in fault.detail
    assert value(truth, [*ON, "press_timer"], "delay") == 1
    assert value(faulty, [*ON, "press_timer"], "delay") == 0
    assert value(faulty, [*ON, "press_timer", "press_timer"], "delay") == 1
    # and the reverse: the belief applies where the truth only shows
    again, back = every_candidate(on_entry, faulty, "set_delay")[0]
    assert "changes delay (it only shows it)" in back.detail
    assert value(again, [*ON, "press_timer"], "delay") == 1


def test_side_effect_missing_wrong_or_invented() -> None:
    truth = oven()
    power = every_candidate(side_effect, truth, "power")
    faulty, _ = only(power, lambda f: "no longer resets delay" in f.detail)
    off_and_on = [*ON, "press_timer", "press_power", "press_power"]
    assert value(truth, off_and_on, "delay") == 0
    assert value(faulty, off_and_on, "delay") == 1
    stop = every_candidate(side_effect, truth, "stop")
    faulty, _ = only(stop, lambda f: "also resets mode" in f.detail)
    stopped = [*ON, "press_mode", "press_start", "press_stop"]
    assert value(truth, stopped, "mode") == "grill"
    assert value(faulty, stopped, "mode") == "bake"
    mode = every_candidate(side_effect, truth, "set_mode")  # choosing a programme…
    faulty, _ = only(mode, lambda f: "also resets delay" in f.detail)
    assert value(truth, [*ON, "press_timer", "press_mode"], "delay") == 1
    assert value(faulty, [*ON, "press_timer", "press_mode"], "delay") == 0
    assert every_candidate(side_effect, truth, "set_delay") == []  # TIMER: nothing to misread


def test_side_effect_invents_a_start_for_a_one_touch_key() -> None:
    text = (
        OVEN.replace(
            "  - {id: stop_button, label: STOP}",
            "  - {id: stop_button, label: STOP}\n  - {id: quick_button, label: QUICK}",
        )
        .replace(
            "  press_stop: {control: stop_button}",
            "  press_stop: {control: stop_button}\n  press_quick: {control: quick_button}",
        )
        .replace(
            "  start:\n",
            "  quick:\n    - {actions: [press_quick], variable: delay, effect: {to: 3}}\n"
            "  start:\n",
        )
    )
    truth = model_from(text)
    faulty, _ = only(
        every_candidate(side_effect, truth, "quick"), lambda f: "sets running to 'on'" in f.detail
    )
    assert value(truth, [*ON, "press_quick"], "running") == "off"
    assert value(faulty, [*ON, "press_quick"], "running") == "on"


def test_side_effect_sets_a_wrong_value() -> None:
    text = oven_text_with_level()
    truth = model_from(text)
    candidates = every_candidate(side_effect, truth, "start")
    faulty, fault = only(candidates, lambda f: "instead of" in f.detail)
    assert "sets fan to" in fault.detail
    assert value(truth, [*ON, "press_start"], "fan") == "high"
    assert value(faulty, [*ON, "press_start"], "fan") in ("auto", "turbo")  # a neighbour


def oven_text_with_level() -> str:
    text = OVEN.replace(
        '  running: {type: discrete, values: ["off", "on"]}',
        '  running: {type: discrete, values: ["off", "on"]}\n'
        "  fan: {type: discrete, values: [low, auto, high, turbo]}",
    )
    text = text.replace(
        '    - {actions: [press_start], variable: running, effect: {to: "on"}}',
        '    - {actions: [press_start], variable: running, effect: {to: "on"}, set: {fan: high}}\n'
        "  set_fan:\n    - {actions: [press_fan], variable: fan, effect: next}",
    )
    text = text.replace(
        "  - {id: stop_button, label: STOP}",
        "  - {id: stop_button, label: STOP}\n  - {id: fan_button, label: FAN}",
    )
    return text.replace(
        "  press_stop: {control: stop_button}",
        "  press_stop: {control: stop_button}\n  press_fan: {control: fan_button}",
    )


def test_misplaced_action_files_the_entry_key_under_another_feature() -> None:
    truth = oven()
    candidates = every_candidate(misplaced_action, truth, "set_temperature")
    faulty, fault = only(candidates, lambda f: "to features.set_mode[0]" in f.detail)
    assert "press_temp moved from features.set_temperature[0]" in fault.detail
    # the belief: TEMP steps the mode, and ▲ alone enters the temperature setting
    assert value(faulty, [*ON, "press_temp"], "mode") == "grill"
    assert value(truth, [*ON, "press_temp"], "mode") == "bake"
    assert value(faulty, [*ON, "press_up"], "temperature") == 200
    assert not press(truth, [*ON, "press_up"])[1].accepted


def test_misplaced_action_moves_one_key_of_a_pair() -> None:
    text = oven_text_wrapping()
    truth = model_from(text)
    candidates = every_candidate(misplaced_action, truth, "set_temperature", seeds=8)
    faulty, fault = only(candidates, lambda f: f.detail.startswith("press_down moved"))
    assert "press_down" not in faulty.features["set_temperature"][1].actions
    target = fault.detail.split(" to ")[1].split(" ")[0]
    feature, index = target.removeprefix("features.").rstrip("]").split("[")
    assert "press_down" in faulty.features[feature][int(index)].actions


def oven_text_wrapping() -> str:
    return OVEN.replace("    label: TEMPERATURE\n", "    label: TEMPERATURE\n    wrap: true\n")


def test_merged_features_make_start_follow_the_setting() -> None:
    truth = oven()
    ((faulty, fault),) = every_candidate(merged_features, truth, "set_delay")
    assert fault.detail.startswith("set_delay and start read as one procedure")
    assert "start" not in faulty.features
    assert value(truth, [*ON, "press_start"], "running") == "on"
    assert not press(faulty, [*ON, "press_start"])[1].accepted  # only after the delay now
    assert value(faulty, [*ON, "press_timer", "press_start"], "running") == "on"
    assert shown(faulty, [*ON, "press_timer"]) == "DL1 h"
