"""Two cheap ways out of a search that would otherwise walk every setting's values: a goal
variable out of reach on its own proves the whole goal out of reach, and a key in front of a
setting's steps that sets it (a TIME key showing 7:00 before the dial turns) tells the bound
where the setting's own route starts. Both shapes come from read beliefs the loop repaired
(a keypad that lost a digit key; a learnt ``set`` on an entry step), where the search ran to
its work limit before."""

from __future__ import annotations

import pytest

from apbot.model.goal import parse_goal
from apbot.plan import search
from apbot.plan.bounds import LowerBound
from apbot.plan.goals import CompiledGoal
from apbot.plan.plan import Unreachable, plan
from apbot.sim.compiled import State, compiled_model
from apbot.testing.bfs import distances_to_goal
from tests.helpers import model_from

# a keypad that lost its 3 (temperature) beside a dial-walked timer and two switches
NO_THREE = """
controls: [{id: power}, {id: fan}, {id: swing}, {id: temp}, {id: timer}, {id: plus},
           {id: minus}, {id: d0, kind: key}, {id: d1, kind: key}, {id: d2, kind: key},
           {id: d4, kind: key}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  fan: {type: discrete, values: ["off", "on"]}
  swing: {type: discrete, values: ["off", "on"]}
  temp: {type: numeric, ranges: [[16, 31, 1]],
         entry: {format: number, overflow: shift}}
  timer: {type: time, ranges: [["00:01:00", "02:00:00", 60]]}
actions: {press_power: {control: power}, press_fan: {control: fan},
          press_swing: {control: swing}, press_temp: {control: temp},
          press_timer: {control: timer}, press_plus: {control: plus},
          press_minus: {control: minus}, press_0: {control: d0, digit: 0},
          press_1: {control: d1, digit: 1}, press_2: {control: d2, digit: 2},
          press_4: {control: d4, digit: 4}}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  fan: [{actions: [press_fan], variable: fan, effect: toggle}]
  swing: [{actions: [press_swing], variable: swing, effect: toggle}]
  set_temp:
    - {actions: [press_temp]}
    - actions: [press_0, press_1, press_2, press_4]
      variable: temp
      effect: {press_0: digit, press_1: digit, press_2: digit, press_4: digit}
  set_timer:
    - {actions: [press_timer]}
    - {actions: [press_plus, press_minus], variable: timer,
       effect: {press_plus: next, press_minus: prev}}
guards:
  - {when: {power: "off"}, only: [press_power]}
"""


def test_one_part_out_of_reach_ends_the_search_at_once() -> None:
    """31 cannot be typed without a 3: the whole goal is out of reach, and the search says
    so after a few thousand successors instead of walking every timer value and switch."""
    model = model_from(NO_THREE)
    goal = {"temp": 31, "timer": "01:10:00", "fan": "on", "swing": "on", "power": "on"}
    with pytest.raises(Unreachable) as caught:
        plan(model, None, goal)
    assert not caught.value.budget_hit
    assert caught.value.generated < 40_000
    # the same question without the part proof walks far more (the proof is what cut it)
    compiled = compiled_model(model)
    target = CompiledGoal.build(compiled, parse_goal(model, goal))
    whole = search.TaskSearch(compiled, target)
    whole._part_out_of_reach = lambda start, left: (False, 0)  # type: ignore[method-assign]
    with pytest.raises(search.SearchExhausted):
        whole.run(compiled.initial_state())
    assert whole.generated > 4 * caught.value.generated
    # a reachable goal is still planned, and as short as before
    assert len(plan(model, None, {"temp": 24, "timer": "00:03:00", "power": "on"})) == 7


def test_a_part_proof_respects_the_longest_plan_wanted() -> None:
    """With ``most``, a part that needs more actions than allowed is out of reach too."""
    model = model_from(NO_THREE)
    goal = {"timer": "02:00:00", "fan": "on", "swing": "on", "power": "on"}
    assert len(plan(model, None, goal)) == 123
    with pytest.raises(Unreachable, match="at most 100"):
        plan(model, None, goal, most=100)


# TIME and TEMP keys show their defaults (1:30, 200°) before the dial turns: the values now
# are no start for the dial, and a bound that thinks so makes the search walk a plateau
SET_ON_ENTRY = """
controls: [{id: power}, {id: start}, {id: temp}, {id: time}, {id: plus}, {id: minus}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  running: {type: discrete, values: ["off", "on"]}
  temp: {type: numeric, ranges: [[80, 230, 10]]}
  time: {type: time, ranges: [["00:00:00", "02:00:00", 60]]}
actions: {press_power: {control: power}, press_start: {control: start},
          press_temp: {control: temp}, press_time: {control: time},
          press_plus: {control: plus}, press_minus: {control: minus}}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  start: [{actions: [press_start], variable: running, effect: toggle}]
  set_temp:
    - {actions: [press_temp], set: {temp: 200}}
    - {actions: [press_plus, press_minus], variable: temp,
       effect: {press_plus: next, press_minus: prev}}
  set_time:
    - {actions: [press_time], set: {time: "01:30:00"}}
    - {actions: [press_plus, press_minus], variable: time,
       effect: {press_plus: next, press_minus: prev}}
guards:
  - {when: {power: "off"}, only: [press_power]}
  - {when: {running: "on"}, only: [press_start, press_power]}
"""


def test_a_key_that_sets_the_value_on_entry_starts_the_bound_there() -> None:
    model = model_from(SET_ON_ENTRY)
    compiled = compiled_model(model)
    goal = parse_goal(model, {"temp": 90, "time": "01:10:00", "running": "on"})
    bound = LowerBound(compiled, CompiledGoal.build(compiled, goal))
    start = compiled.initial_state()  # temp 80, time 0:00, off
    # power, TEMP, 11 presses from 200 down to 90, TIME, 20 from 1:30 down to 1:10, START
    found = plan(model, None, goal)
    assert len(found) == 35
    assert bound(start, continuing=True) >= 34  # was 4: one press from 80, TIME, START, power
    assert found.generated < 2_000
    # admissible on every state that reaches the goal, and 0 on goal states
    _states, distance = distances_to_goal(compiled, goal, max_states=100_000)
    assert distance[start] == 35
    assert all(bound(state) <= steps for state, steps in distance.items())
    assert all(bound(state) == 0 for state, steps in distance.items() if steps == 0)


# two programmes: 170° only for BAKE, 1:30 only for SLOW
TWO_PROGRAMMES = """
controls: [{id: menu}, {id: temp}, {id: time}, {id: plus}, {id: light}]
variables:
  menu: {type: discrete, values: [bake, slow]}
  light: {type: discrete, values: ["off", "on"]}
  temp:
    type: numeric
    depends_on: menu
    cases: {bake: {ranges: [[80, 230, 10]]}, slow: {ranges: [[40, 80, 10]]}}
  time:
    type: time
    depends_on: menu
    cases: {bake: {ranges: [["00:01:00", "01:00:00", 60]]},
            slow: {ranges: [["00:01:00", "02:00:00", 60]]}}
actions: {press_menu: {control: menu}, press_temp: {control: temp},
          press_time: {control: time}, press_plus: {control: plus},
          press_light: {control: light}}
features:
  menu: [{actions: [press_menu], variable: menu, effect: next}]
  light: [{actions: [press_light], variable: light, effect: toggle}]
  set_temp:
    - {actions: [press_temp]}
    - {actions: [press_plus], variable: temp, effect: next}
  set_time:
    - {actions: [press_time]}
    - {actions: [press_plus], variable: time, effect: next}
"""


def test_settings_no_programme_has_together_are_out_of_reach_without_a_search() -> None:
    model = model_from(TWO_PROGRAMMES)
    with pytest.raises(Unreachable, match="no programme lets") as caught:
        plan(model, None, {"temp": 170, "time": "01:30:00", "light": "on"})
    assert not caught.value.budget_hit
    assert caught.value.generated == 0
    # each alone, or both where one programme has them, is planned as before
    assert len(plan(model, None, {"temp": 170, "time": "00:30:00"})) == 10 + 30
    assert len(plan(model, None, {"time": "01:30:00", "temp": 60})) == 1 + 3 + 90


def test_the_part_proofs_stop_where_the_whole_search_s_work_runs_out(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The part proofs are work done for the whole search: once they have spent what it has
    left, no further part is searched, and each part may spend only what is left (rather
    than up to 20,000 successors per part past it)."""
    model = model_from(NO_THREE)
    goal = {"temp": 24, "timer": "01:10:00", "fan": "on", "swing": "on", "power": "on"}
    compiled = compiled_model(model)
    whole = search.TaskSearch(compiled, CompiledGoal.build(compiled, parse_goal(model, goal)))
    works: list[int] = []
    real_run = search.TaskSearch.run

    def counted(self: search.TaskSearch, start: State) -> search.SearchResult:
        works.append(self.work)
        return real_run(self, start)

    monkeypatch.setattr(search.TaskSearch, "run", counted)
    assert whole._part_out_of_reach(compiled.initial_state(), 10**9)[0] is False
    assert len(works) == len(goal) and max(works) == search.PART_WORK
    works.clear()
    whole._part_out_of_reach(compiled.initial_state(), 30)
    assert works[0] == 30 and len(works) < len(goal)  # each part has what the others left
