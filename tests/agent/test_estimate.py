"""State estimation reads feedback in the belief's names and spellings, and keeps apart what
the belief cannot explain."""

from __future__ import annotations

import random

import pytest

from apbot.agent.environment import Feedback, SimulatorEnvironment
from apbot.agent.estimate import Estimate, StateEstimator
from apbot.bench.suite import load_suite
from apbot.model.schema import ApplianceModel
from tests.helpers import model_from

FAN = """
controls:
  - {id: power, label: POWER}
  - {id: speed, label: SPEED}
  - {id: swing, label: SWING}
  - {id: prog, label: PROG}
  - {id: timer, label: TIMER}
  - {id: up, label: "+"}
  - {id: down, label: "-"}
  - {id: lock, label: LOCK}
variables:
  power: {type: discrete, values: ["off", "on"]}
  speed: {type: discrete, values: [%(speeds)s]}
  swing: {type: discrete, values: ["off", "on"]}
  programme: {type: discrete, values: [normal, eco, sleep]}
  timer: {type: time, ranges: [["00:00:00", "08:00:00", 1800]], format: "h:mm"}
  temperature: {type: numeric, unit: "°C", ranges: [[16, 30, 1]], initial: 20}
  child_lock: {type: discrete, values: ["off", "on"]}
actions:
  press_power: {control: power}
  press_speed: {control: speed}
  press_swing: {control: swing}
  press_prog: {control: prog}
  press_timer: {control: timer}
  press_up: {control: up}
  press_down: {control: down}
  hold_lock: {control: lock, skill: hold, seconds: 3}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  speed: [{actions: [press_speed], variable: speed}]
  swing: [{actions: [press_swing], variable: swing, effect: toggle}]
  programme: [{actions: [press_prog], variable: programme}]
  timer:
    - {actions: [press_timer]}
    - {actions: [press_up, press_down], variable: timer, effect: {press_up: next, press_down: prev}}
  temperature:
    - {actions: [press_up, press_down], variable: temperature,
       effect: {press_up: next, press_down: prev}}
  lock: [{actions: [hold_lock], variable: child_lock, effect: toggle}]
"""


def fan(speeds: str = '"off", low, medium, high') -> ApplianceModel:
    return model_from(FAN % {"speeds": speeds})


def read(estimator: StateEstimator, values: dict[str, object], **context: object) -> Estimate:
    return estimator.estimate(Feedback("", values), context=context or None)


@pytest.mark.parametrize(
    "appliance", load_suite("bundled").appliances, ids=lambda a: a.model.appliance.id
)
def test_the_simulators_own_feedback_maps_one_to_one(appliance) -> None:
    env = SimulatorEnvironment(appliance.model)
    estimator = StateEstimator(appliance.model)
    rng = random.Random(appliance.model.appliance.id)
    feedback = env.reset()
    for _ in range(40):
        for context in (env.simulator.assignment(), None):
            seen = estimator.estimate(feedback, context=context)
            assert seen.values == {k: v for k, v in feedback.values.items() if v is not None}
            assert seen.mapping == {k: k for k in feedback.values}
            assert not seen.outside and not seen.unmatched
        feedback = env.step(rng.choice(env.actions))


def test_renamed_keys_and_other_spellings_are_read() -> None:
    seen = read(
        StateEstimator(fan()),
        {
            "Spd": "Medium",
            "Temp": "25°C",
            "TIMER": "1:30",
            "Program": "Eco",
            "ChildLock": "ON",
            "Power": True,
        },
    )
    assert seen.values == {
        "speed": "medium",
        "temperature": 25,
        "timer": "01:30:00",
        "programme": "eco",
        "child_lock": "on",
        "power": "on",
    }
    assert seen.mapping == {
        "Spd": "speed",
        "Temp": "temperature",
        "TIMER": "timer",
        "Program": "programme",
        "ChildLock": "child_lock",
        "Power": "power",
    }
    assert not seen.unmatched and not seen.outside


def test_a_switch_reported_as_a_bool_or_in_capitals() -> None:
    estimator = StateEstimator(fan())
    assert read(estimator, {"swing": True, "power": False, "lock": "ON"}).values == {
        "power": "off",
        "swing": "on",
        "child_lock": "on",
    }


def test_an_ambiguous_name_is_reported_not_guessed() -> None:
    estimator = StateEstimator(fan())
    seen = read(estimator, {"t": None})
    assert seen.unmatched == {"t": "'t' could be timer or temperature"}
    seen = read(estimator, {"s": "off"})  # speed and swing both have "off"
    assert seen.unmatched == {"s": "'s' could be speed or swing"} and not seen.values


def test_the_value_decides_between_similar_names_and_the_choice_sticks() -> None:
    estimator = StateEstimator(fan())
    assert read(estimator, {"s": "on"}).values == {"swing": "on"}  # only swing has "on"
    assert read(estimator, {"s": "off"}).values == {"swing": "off"}  # learnt, no longer ambiguous
    assert read(estimator, {"t": "2 h"}).values == {"timer": "02:00:00"}  # only a time fits


def test_a_similar_name_must_be_able_to_hold_the_value() -> None:
    seen = read(StateEstimator(fan()), {"SpinSpeed": 1200, "humidity": 50})
    assert set(seen.unmatched) == {"SpinSpeed", "humidity"} and not seen.values
    assert "can show 1200" in seen.unmatched["SpinSpeed"]


def test_values_outside_the_belief_domain_are_evidence_not_errors() -> None:
    estimator = StateEstimator(fan('"off", low, high'))
    seen = read(estimator, {"temperature": 35, "speed": " Turbo ", "timer": "9:00", "Spd": 1})
    assert seen.outside == {"temperature": 35, "speed": "Turbo", "timer": "09:00:00"}
    assert not seen.values
    seen = read(estimator, {"Temp": "35°C"})
    assert seen.outside == {"temperature": 35}


def test_a_value_that_cannot_be_read_names_the_variable() -> None:
    seen = read(StateEstimator(fan()), {"temperature": "hot", "timer": "--"})
    assert (
        "temperature" in seen.unmatched["temperature"] and "'hot'" in seen.unmatched["temperature"]
    )
    assert "timer" not in seen.unmatched and not seen.values  # "--": nothing shown


def test_one_feedback_name_per_variable() -> None:
    estimator = StateEstimator(fan())
    seen = read(estimator, {"temperature": 20, "Temp": 21})
    assert seen.values == {"temperature": 20}
    assert seen.unmatched == {"Temp": "temperature is already shown as 'temperature'"}
    seen = read(StateEstimator(fan()), {"Temp": 20, "TEMP": 21})  # equally good: neither
    assert not seen.values
    assert seen.unmatched["TEMP"] == "'Temp' and 'TEMP' both look like temperature"


def test_a_dependent_setting_is_read_against_the_current_programme(washer) -> None:
    estimator = StateEstimator(washer)
    assert read(estimator, {"temperature": "90"}).values == {"temperature": "90"}
    assert read(estimator, {"temperature": "90"}, programme="cotton").values == {
        "temperature": "90"
    }
    assert read(estimator, {"temperature": "90"}, programme="wool").outside == {"temperature": "90"}
    # a programme shown in the same feedback takes precedence over the belief's
    seen = read(estimator, {"spin_speed": 1000, "programme": "wool"}, programme="cotton")
    assert list(seen.values) == ["programme"] and seen.outside == {"spin_speed": 1000}


def test_rebind_keeps_learnt_names_and_uses_the_repaired_domains() -> None:
    estimator = StateEstimator(fan('"off", low, high'))
    assert read(estimator, {"s": "on"}).values == {"swing": "on"}
    assert read(estimator, {"speed": "medium"}).outside == {"speed": "medium"}
    estimator.rebind(fan('"off", low, medium, high'))
    assert read(estimator, {"speed": "medium"}).values == {"speed": "medium"}
    assert read(estimator, {"s": "off"}).values == {"swing": "off"}


def test_results_are_fresh_objects() -> None:
    estimator = StateEstimator(fan())
    first = read(estimator, {"Spd": "low", "humidity": 3})
    first.values.clear(), first.mapping.clear(), first.unmatched.clear()
    again = read(estimator, {"Spd": "low", "humidity": 3})
    assert again.values == {"speed": "low"} and again.mapping == {"Spd": "speed"}
    assert set(again.unmatched) == {"humidity"}
