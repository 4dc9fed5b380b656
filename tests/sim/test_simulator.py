"""The semantics every model relies on: feature pointer, effects, guards, keypad, display."""

from __future__ import annotations

import math
import random

import numpy as np
import pytest

from apbot.model.domain import ValueProblem
from apbot.model.schema import ApplianceModel
from apbot.sim.simulator import Simulator, UnknownAction, UnknownVariable
from tests.helpers import model_from

CLOCK = """
controls:
  - {id: clock_key, label: CLOCK}
  - {id: up_key, label: UP}
  - {id: down_key, label: DOWN}
  - {id: mode_key, label: MODE}
variables:
  hour: {type: numeric, ranges: [[0, 23, 1]], initial: 12}
  minute: {type: numeric, ranges: [[0, 59, 1]], wrap: true}
  mode: {type: discrete, values: [auto, eco, boost]}
actions:
  press_clock: {control: clock_key}
  press_up: {control: up_key}
  press_down: {control: down_key}
  press_mode: {control: mode_key}
features:
  set_clock:
    - {actions: [press_clock]}
    - actions: [press_up, press_down]
      variable: hour
      effect: {press_up: next, press_down: prev}
    - {actions: [press_clock]}
    - actions: [press_up, press_down]
      variable: minute
      effect: {press_up: next, press_down: prev}
  mode:
    - {actions: [press_mode], variable: mode, effect: next, on_entry: show}
"""


def run(sim: Simulator, *actions: str) -> list[str]:
    return [sim.step(a).display for a in actions]


def test_feature_pointer_walks_a_procedure() -> None:
    sim = Simulator(model_from(CLOCK))
    assert not sim.step("press_up").accepted  # up belongs to no first step: nothing to adjust
    run(sim, "press_clock", "press_up", "press_up")
    assert sim.value("hour") == 14
    run(sim, "press_clock", "press_down")  # clock again: advance to the minutes
    assert (sim.value("hour"), sim.value("minute")) == (14, 59)  # minutes wrap
    assert sim.step("press_up").display == "MINUTE 0"


def test_first_press_can_just_show_the_value() -> None:
    sim = Simulator(model_from(CLOCK))
    assert sim.step("press_mode").display == "MODE auto"
    assert sim.step("press_mode").display == "MODE eco"
    sim.step("press_clock")
    assert sim.step("press_mode").display == "MODE eco"  # re-entering shows again


def test_guards_refuse_with_the_guard_display(washer: ApplianceModel) -> None:
    sim = Simulator(washer)
    assert sim.observe().display == ""  # dark while off (hide)
    refused = sim.step("press_temp")
    assert not refused.accepted and "power off" in refused.reason
    sim.step("press_power")
    assert sim.step("press_start").values["running"] == "on"
    refused = sim.step("press_spin")
    assert (refused.accepted, refused.display) == (False, "RUNNING")
    assert sim.step("hold_temp_and_spin").accepted  # the lock is allowed while running
    refused = sim.step("press_start")
    assert (refused.accepted, refused.display) == (False, "LOCK")


def test_holds_need_their_duration(washer: ApplianceModel) -> None:
    sim = Simulator(washer)
    sim.step("press_power")
    short = sim.step("hold_temp_and_spin", seconds=1)
    assert not short.accepted and "held for 3 s" in short.reason
    assert sim.step("hold_temp_and_spin", seconds=3.5).accepted
    assert sim.value("child_lock") == "on"


def test_programme_change_restores_its_defaults(washer: ApplianceModel) -> None:
    sim = Simulator(washer)
    sim.step("press_power")
    run(sim, "press_temp", "press_temp")
    assert sim.value("temperature") == "90"
    sim.step("turn_programme_cw")  # cotton -> eco 40-60
    assert (sim.value("temperature"), sim.value("spin_speed")) == ("40", 1400)
    sim.step("turn_programme_ccw")
    assert sim.value("temperature") == "40"  # cotton's default, not the 90 set before
    sim.step("turn_programme_ccw")  # wrap back to rinse and spin: no temperature there
    assert sim.value("programme") == "rinse and spin"
    assert sim.value("temperature") is None
    observation = sim.step("press_temp")
    assert observation.accepted and observation.display == "TEMP --"


def test_keypad_digits_shift_in_and_reset_on_leaving(microwave: ApplianceModel) -> None:
    sim = Simulator(microwave)
    displays = run(sim, "press_time_cook", "press_1", "press_3", "press_0")
    assert displays == ["COOK 00:00", "COOK 00:01", "COOK 00:13", "COOK 01:30"]
    run(sim, "press_4", "press_5")  # shift: 0130 -> 1304 -> 3045
    assert sim.value("cook_time") == "00:30:45"
    run(sim, "press_power_level", "press_7")  # a fresh buffer for another variable
    assert (sim.value("power_level"), sim.value("cook_time")) == (7, "00:30:45")
    run(sim, "press_clock", "press_9", "press_7", "press_5")  # 9:75 is not a time: unchanged
    assert sim.value("clock") == "12:00:00"


def test_keypad_overflow_ignore() -> None:
    sim = Simulator(
        model_from("""
controls:
  - {id: key_1, kind: key, label: "1"}
  - {id: key_2, kind: key, label: "2"}
  - {id: set_key, label: SET}
variables:
  grams:
    type: numeric
    ranges: [[0, 99, 1]]
    entry: {format: number, max_digits: 2, overflow: ignore}
actions:
  press_set: {control: set_key}
  press_1: {control: key_1, digit: 1}
  press_2: {control: key_2, digit: 2}
features:
  weight:
    - {actions: [press_set]}
    - {actions: [press_1, press_2], variable: grams}
""")
    )
    run(sim, "press_set", "press_1", "press_2", "press_1")
    assert sim.value("grams") == 12


def test_add_snaps_and_starts(microwave: ApplianceModel) -> None:
    sim = Simulator(microwave)
    observation = sim.step("press_add30")
    assert observation.display == "COOK 00:30"
    assert sim.value("running") == "on"  # a side effect of the +30 s key
    sim.step("press_add30")
    assert sim.value("cook_time") == "00:01:00"
    sim.step("press_stop")  # resets cook time and stops
    assert (sim.value("cook_time"), sim.value("running")) == ("00:00:00", "off")


def test_idle_display_and_indicators(microwave: ApplianceModel) -> None:
    sim = Simulator(microwave)
    observation = sim.observe()
    assert observation.display == "12:00"
    assert observation.values == {"clock": "12:00:00", "child_lock": "off"}


def test_states_are_values_restorable_and_deterministic(washer: ApplianceModel) -> None:
    rng = random.Random(7)
    actions = [rng.choice(Simulator(washer).actions) for _ in range(300)]
    first, second = Simulator(washer), Simulator(washer)
    states = []
    for action in actions:
        first.step(action)
        second.step(action)
        states.append(first.state)
        assert first.state == second.state
    assert len(set(states)) > 5  # hashable, and the walk went somewhere
    middle = states[150]
    display = Simulator(washer).reset(middle).display
    first.reset(middle)
    assert first.state == middle and first.observe().display == display


def test_choosing_the_programme_again_restores_its_defaults() -> None:
    sim = Simulator(
        model_from("""
controls: [{id: p, label: POWER}, {id: t, label: TEMP}, {id: c, label: COTTON},
           {id: w, label: WOOL}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  programme: {type: discrete, values: [cotton, wool]}
  temperature: {type: discrete, depends_on: programme,
                cases: {cotton: {values: ["20", "40", "60"], initial: "40"}, wool: ["20", "30"]}}
actions: {press_power: {control: p}, press_temp: {control: t}, press_cotton: {control: c},
          press_wool: {control: w}}
features:
  power: [{actions: [press_power], variable: power, effect: toggle, reset: [programme]}]
  temperature: [{actions: [press_temp], variable: temperature}]
  programme:
    - {actions: [press_cotton, press_wool], variable: programme,
       effect: {press_cotton: {to: cotton}, press_wool: {to: wool}}}
""")
    )
    run(sim, "press_power", "press_temp")
    assert sim.value("temperature") == "60"
    sim.step("press_cotton")  # cotton again: its defaults come back
    assert sim.value("temperature") == "40"
    run(sim, "press_temp", "press_power")  # switching off forgets settings, cotton or not
    assert sim.value("temperature") == "40"


# --- the Python API refuses bad arguments by name ------------------------------------------------


def test_a_simulator_needs_a_model() -> None:
    with pytest.raises(TypeError, match=r"Simulator needs an ApplianceModel .* not NoneType"):
        Simulator(None)  # type: ignore[arg-type]


def test_satisfies_names_an_unknown_variable_and_an_impossible_value(
    washer: ApplianceModel,
) -> None:
    sim = Simulator(washer)
    with pytest.raises(UnknownVariable, match="no variable 'programe'; did you mean 'programme'"):
        sim.satisfies({"programe": "wool"})
    with pytest.raises(ValueError, match="no variable 'nosuch'"):
        sim.satisfies({"nosuch": 1})
    with pytest.raises(ValueProblem, match=r"goal temperature=81: '81' is not one of"):
        sim.satisfies({"temperature": 81})
    with pytest.raises(TypeError, match="a goal maps variable names to values"):
        sim.satisfies(["power=on"])  # type: ignore[arg-type]
    assert sim.satisfies({"power": False, "programme": "Cotton"})  # any accepted notation
    assert not sim.satisfies({"power": "on"})


@pytest.mark.parametrize(
    ("seconds", "error", "message"),
    [
        ("3", TypeError, "a number; got str '3'"),
        (True, TypeError, "a number; got bool True"),
        (math.nan, ValueError, "finite number above zero; got nan"),
        (math.inf, ValueError, "finite number above zero; got inf"),
        (-5, ValueError, "finite number above zero; got -5"),
        (0, ValueError, "finite number above zero; got 0"),
    ],
)
def test_a_hold_needs_a_positive_finite_duration(
    washer: ApplianceModel, seconds: object, error: type[Exception], message: str
) -> None:
    sim = Simulator(washer)
    sim.step("press_power")
    before = sim.state
    with pytest.raises(error, match=message):
        sim.step("hold_temp_and_spin", seconds)  # type: ignore[arg-type]
    assert sim.state == before  # nothing happened
    assert sim.step("hold_temp_and_spin", 3.0).accepted


def test_an_action_index_is_checked_not_wrapped(washer: ApplianceModel) -> None:
    sim = Simulator(washer)
    count = len(sim.actions)
    with pytest.raises(UnknownAction, match=f"index -1 is out of range: the model has {count}"):
        sim.step(-1)  # Python's negative index used to press the last action
    with pytest.raises(ValueError, match=f"index {count} is out of range"):
        sim.step(count)
    with pytest.raises(TypeError, match=r"not float 1\.5"):
        sim.step(1.5)  # type: ignore[arg-type]
    assert sim.step(np.int64(0)).accepted == sim.step(0).accepted


def test_reset_to_a_state_checks_it(washer: ApplianceModel) -> None:
    sim = Simulator(washer)
    state = sim.state
    with pytest.raises(TypeError, match="state must be a State"):
        sim.reset(tuple(state))  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"values\[0\]: 7 is not an index of power's 2 values"):
        sim.reset(state._replace(values=(7, *state.values[1:])))
    with pytest.raises(ValueError, match="step must be -1 or a step id"):
        sim.reset(state._replace(step=10_000))
    with pytest.raises(ValueError, match="buffer must be a string of typed digits"):
        sim.reset(state._replace(buffer="12a"))
    assert sim.reset(state).display == Simulator(washer).observe().display
