"""The abstraction's proof that a goal is out of reach is sound: whenever it says so, brute
force finds no way either — on every checked state of generated models, and on the shape of
the read beliefs that made the search run to its work limit."""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from apbot.model.goal import parse_goal
from apbot.plan.abstract import out_of_reach
from apbot.plan.goals import CompiledGoal
from apbot.plan.plan import Unreachable, plan
from apbot.sim.compiled import compiled_model
from apbot.testing.bfs import distances_to_goal
from apbot.testing.generate import random_goal, random_model
from tests.helpers import model_from
from tests.plan.budget import BOUND, states_bucket

EXAMPLES, MODEL_STATES = BOUND


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(min_value=0, max_value=2**32 - 1))
def test_out_of_reach_only_where_brute_force_finds_no_way(seed: int) -> None:
    rng = random.Random(seed)
    model = random_model(rng, max_states=MODEL_STATES)
    goal = parse_goal(model, random_goal(rng, model))
    compiled = compiled_model(model)
    states, distance = distances_to_goal(compiled, goal, max_states=MODEL_STATES)
    event(states_bucket(len(states)))
    target = CompiledGoal.build(compiled, goal)
    proved = 0
    for state in rng.sample(states, min(len(states), 30)):
        if out_of_reach(compiled, target, state):
            proved += 1
            assert state not in distance, f"seed {seed}: {state} reaches {goal} in {distance}"
    event("some state proved out of reach" if proved else "none proved out of reach")


LOCK_AND_START = """
controls: [{id: start}, {id: cancel}, {id: lock}, {id: colour}, {id: plus}]
variables:
  running: {type: discrete, values: ["off", "on"]}
  child_lock: {type: discrete, values: ["off", "on"]}
  colour: {type: discrete, values: [light, medium, dark]}
  time: {type: time, ranges: [["00:01:00", "04:00:00", 60]]}
actions: {press_start: {control: start}, press_cancel: {control: cancel},
          hold_lock: {control: lock, skill: hold, seconds: 3}, press_colour: {control: colour},
          press_plus: {control: plus}}
features:
  start: [{actions: [press_start], variable: running, effect: {to: "on"}}]
  cancel: [{actions: [press_cancel], variable: running, effect: {to: "off"}}]
  lock: [{actions: [hold_lock], variable: child_lock, effect: toggle}]
  set_colour: [{actions: [press_colour], variable: colour, effect: next}]
  set_time: [{actions: [press_plus], variable: time, effect: next}]
guards:
  - {when: {child_lock: "on"}, only: [hold_lock]}
  - {when: {running: "on"}, only: [press_start, press_cancel]}
"""


def test_a_lock_that_stops_the_start_key_is_out_of_reach_at_once() -> None:
    """Locked, START is refused; running, the lock key is. A read bread maker's belief had
    this shape, and the search walked every colour and time before saying so."""
    model = model_from(LOCK_AND_START)
    compiled = compiled_model(model)
    goal = parse_goal(model, {"running": "on", "child_lock": "on", "time": "02:30:00"})
    assert out_of_reach(compiled, CompiledGoal.build(compiled, goal), compiled.initial_state())
    with pytest.raises(Unreachable, match="hold together") as caught:
        plan(model, None, goal, work=100_000)
    assert not caught.value.budget_hit
    fine = parse_goal(model, {"running": "on", "time": "02:30:00"})
    assert not out_of_reach(compiled, CompiledGoal.build(compiled, fine), compiled.initial_state())
    assert len(plan(model, None, fine)) == 150
