"""Faults in what the model holds: a missing setting, an invented one, wrong guards."""

from __future__ import annotations

from apbot.bench.faults import guard, missing_variable, spurious_variable
from apbot.bench.faults.structure import guard_names
from tests.bench.faults.models import KEYPAD, every_candidate, only, oven, press, shown, value
from tests.helpers import model_from

ON = ["press_power"]


def test_missing_variable_takes_its_procedure_and_unknown_keys_with_it() -> None:
    truth = oven()
    ((faulty, fault),) = every_candidate(missing_variable, truth, "delay")
    assert fault.detail == "the setting is missing (set_delay removed; press_timer unknown)"
    assert "delay" not in faulty.variables and "set_delay" not in faulty.features
    assert "press_timer" not in faulty.actions
    assert all(c.id != "timer_button" for c in faulty.controls)
    assert "delay" not in faulty.features["power"][0].reset  # references cleaned
    assert "delay" not in faulty.features["stop"][0].reset


def test_missing_variable_in_the_middle_of_a_procedure_leaves_a_plain_key_press() -> None:
    truth = model_from(KEYPAD)
    ((faulty, fault),) = every_candidate(missing_variable, truth, "cook_time")
    assert fault.detail == "the setting is missing (set_time no longer sets it)"
    steps = faulty.features["set_time"]
    assert [s.variable for s in steps] == [None, None, "running"]  # the digits step stays
    assert faulty.display.idle == ""  # the idle display showed the cook time
    typed = ["press_time", "press_1", "press_start"]
    assert value(faulty, typed, "running") == "on"
    one_minute = ["press_time", "press_1", "press_0", "press_0"]
    assert shown(truth, one_minute) == "COOK 01:00"
    assert shown(faulty, one_minute) == "RUNNING off"  # the digits set nothing it knows


def test_missing_variable_never_takes_a_programme_or_run_state() -> None:
    truth = oven()
    assert every_candidate(missing_variable, truth, "mode") == []  # temperature depends on it
    assert every_candidate(missing_variable, truth, "running") == []


def test_spurious_variable_intercepts_the_next_procedures_key() -> None:
    truth = oven()
    candidates = every_candidate(spurious_variable, truth, "set_mode")
    assert any("press_start right after" in f.detail for _, f in candidates)  # START first
    faulty, fault = only(candidates, lambda f: "press_temp right after" in f.detail)
    invented = fault.detail.split()[1]
    assert invented.startswith("mode_") and invented not in truth.variables
    after_mode = [*ON, "press_mode", "press_temp"]
    assert (
        press(truth, after_mode)[0].compiled.focus(press(truth, after_mode)[0].state)
        == (press(truth, after_mode)[0].compiled.var_index["temperature"])
    )
    assert shown(faulty, after_mode).startswith(invented.replace("_", " ").upper())
    assert shown(faulty, [*ON, "press_temp"]) == "TEMPERATURE 180°C"  # elsewhere TEMP still works


def test_spurious_variable_is_not_attached_after_a_key_that_starts_the_appliance() -> None:
    # after START the running guard refuses every key but STOP and POWER in both models
    assert every_candidate(spurious_variable, oven(), "start") == []


def test_guard_missing_narrower_wider_and_wrong_condition() -> None:
    truth = oven()
    assert guard_names(truth) == ["power_off", "running"]
    candidates = every_candidate(guard, truth, "running", seeds=8)
    running = [*ON, "press_start", "press_mode"]
    assert not press(truth, running)[1].accepted
    missing, _ = only(candidates, lambda f: f.detail.endswith("is missing"))
    assert press(missing, running)[1].accepted
    wider, _ = only(candidates, lambda f: "also allows press_mode" in f.detail)
    assert press(wider, running)[1].accepted
    narrower, _ = only(candidates, lambda f: "no longer allows press_stop" in f.detail)
    stopping = [*ON, "press_start", "press_stop"]
    assert press(truth, stopping)[1].accepted and not press(narrower, stopping)[1].accepted


def test_guard_tests_a_wrong_value_of_a_many_valued_state() -> None:
    text = (
        KEYPAD.replace(
            '  running: {type: discrete, values: ["off", "on"]}',
            "  status: {type: discrete, values: [idle, cooking, keep warm]}",
        )
        .replace('variable: running, effect: {to: "on"}', "variable: status, effect: next")
        .replace(
            'display:\n  idle: "{cook_time}"',
            "guards:\n  - {name: busy, when: {status: [cooking, keep warm]}, only: [press_start],"
            ' display: "BUSY"}\ndisplay:\n  idle: "{cook_time}"',
        )
    )
    truth = model_from(text)
    details = {f.detail for _, f in every_candidate(guard, truth, "busy", seeds=12)}
    assert "'busy' (while status is cooking/keep warm) tests status is cooking" in details
