"""Realistic tasks on the example models: plan, then execute on the simulator."""

from __future__ import annotations

import pickle

import pytest

from apbot.model.goal import GoalError
from apbot.model.schema import ApplianceModel
from apbot.plan.plan import Plan, Unreachable, plan
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Simulator
from apbot.testing.bfs import shortest_plan_length
from tests.helpers import model_from


def execute(model: ApplianceModel, found: Plan) -> Simulator:
    sim = Simulator(model)
    for action in found.actions:
        observation = sim.step(action.name, action.seconds)
        assert observation.accepted, (action, observation.reason)
    return sim


def test_washing_machine_six_variables(washer: ApplianceModel) -> None:
    goal = {
        "power": "on",
        "programme": "wool",
        "temperature": "20",
        "spin_speed": "600 rpm",
        "finish_in": "5 h",
        "running": "on",
    }
    found = plan(washer, None, goal)
    features = [m.feature for m in found.macro_actions]
    assert features[0] == "power" and features[-1] == "start_pause"
    assert features.index("select_programme") < min(
        features.index("set_temperature"), features.index("set_spin")
    )
    assert len(found) == 15
    assert execute(washer, found).satisfies(found.goal)
    spin = next(m for m in found.macro_actions if m.feature == "set_spin")
    assert spin.expect == {"spin_speed": 600}


def test_lock_comes_after_start(washer: ApplianceModel) -> None:
    found = plan(washer, None, ["power=on", "programme=cotton", "running=on", "child_lock=on"])
    assert [m.feature for m in found.macro_actions][-2:] == ["start_pause", "child_lock"]
    assert found.actions[-1].seconds == 3


def test_keypad_microwave(microwave: ApplianceModel) -> None:
    found = plan(microwave, None, {"cook_time": "3 min 30 s", "power_level": 5, "running": "on"})
    names = [a.name for a in found.actions]
    assert names[-1] == "press_start"
    assert "press_3" in names and "press_5" in names
    assert len(found) == 7
    assert execute(microwave, found).satisfies(found.goal)


def test_plus_thirty_seconds_beats_typing(microwave: ApplianceModel) -> None:
    found = plan(microwave, None, {"cook_time": "1:30"})
    assert [a.name for a in found.actions] == ["press_add30"] * 3


def test_plans_continue_from_a_half_typed_value(microwave: ApplianceModel) -> None:
    sim = Simulator(microwave)
    for action in ("press_time_cook", "press_1", "press_3"):
        sim.step(action)
    found = plan(microwave, sim.state, {"cook_time": "00:01:30"})
    assert [a.name for a in found.actions] == ["press_0"]


KEYPAD_WITH_CLEAR = """
controls: [{id: k1, kind: key}, {id: k5, kind: key}, {id: k6, kind: key}, {id: clr, label: CLEAR}]
variables:
  level:
    type: numeric
    ranges: [[0, 9, 1]]
    entry: {format: number, max_digits: 3, overflow: OVERFLOW}
actions: {press_1: {control: k1, digit: 1}, press_5: {control: k5, digit: 5},
          press_6: {control: k6, digit: 6}, press_clear: {control: clr}}
features:
  level:
    - actions: [press_1, press_5, press_6, press_clear]
      variable: level
      effect: {press_1: digit, press_5: digit, press_6: digit, press_clear: clear}
"""


@pytest.mark.parametrize("overflow", ["ignore", "shift"])
def test_clear_then_type_when_the_typed_digits_are_in_the_way(overflow: str) -> None:
    """A buffer full with 656: a typed 1 is ignored (or shifts in to 561, and there is no 0
    key for 001); CLEAR, 1 takes two presses."""
    model = model_from(KEYPAD_WITH_CLEAR.replace("OVERFLOW", overflow), check=False)
    sim = Simulator(model)
    for action in ("press_6", "press_5", "press_6"):
        sim.step(action)
    found = plan(model, sim.state, {"level": 1})
    assert [a.name for a in found.actions] == ["press_clear", "press_1"]
    compiled = compiled_model(model)
    assert len(found) == shortest_plan_length(compiled, sim.state, found.goal)


SHOWN_KEYPAD_WITH_CLEAR = """
controls: [{id: k0, kind: key}, {id: k1, kind: key}, {id: k5, kind: key}, {id: clr},
           {id: other}]
variables:
  level: {type: numeric, ranges: [[10, 90, 10]], entry: {format: number}}
  light: {type: discrete, values: ["off", "on"]}
actions: {press_0: {control: k0, digit: 0}, press_1: {control: k1, digit: 1},
          press_5: {control: k5, digit: 5}, press_clear: {control: clr},
          press_light: {control: other}}
features:
  level:
    - actions: [press_0, press_1, press_5, press_clear]
      variable: level
      effect: {press_0: digit, press_1: digit, press_5: digit, press_clear: clear}
      on_entry: show
  light: [{actions: [press_light], variable: light, effect: toggle}]
"""


def test_clear_resets_a_keypad_value_after_the_entering_press() -> None:
    """The first press only shows the value; CLEAR then returns it to its initial 10: two
    presses, where typing 1, 0 after the entering press takes three."""
    model = model_from(SHOWN_KEYPAD_WITH_CLEAR, check=False)
    sim = Simulator(model)
    for action in ("press_5", "press_5", "press_0", "press_light"):  # level 50, then away
        sim.step(action)
    assert sim.value("level") == 50
    found = plan(model, sim.state, {"level": 10})
    assert len(found) == 2 and found.actions[-1].name == "press_clear"
    compiled = compiled_model(model)
    assert len(found) == shortest_plan_length(compiled, sim.state, found.goal)


GUARDED_KEYPAD = """
controls: [{id: set}, {id: k0, kind: key}, {id: k4, kind: key}, {id: k5, kind: key}]
variables:
  mode: {type: discrete, values: [locked, open]}
  level: {type: numeric, ranges: [[0, 90, 10]], entry: {format: number, max_digits: 2}}
actions: {press_set: {control: set}, press_0: {control: k0, digit: 0},
          press_4: {control: k4, digit: 4}, press_5: {control: k5, digit: 5}}
features:
  level:
    - {actions: [press_set]}
    - {actions: [press_0, press_4, press_5], variable: level, set: {mode: open}}
guards:
  - {when: {mode: locked}, only: [press_set, press_5]}
"""


def test_type_on_after_the_only_digit_a_guard_admits() -> None:
    """Locked, only the 5 key works, and any digit unlocks: SET, 5, then 4, 0 shifts the
    buffer to 40 — four presses, without leaving the step to type 40 afresh (five)."""
    model = model_from(GUARDED_KEYPAD, check=False)
    found = plan(model, None, {"level": 40})
    assert [a.name for a in found.actions] == ["press_set", "press_5", "press_4", "press_0"]
    compiled = compiled_model(model)
    assert len(found) == shortest_plan_length(compiled, compiled.initial_state(), found.goal)


def test_dial_oven_clamps_and_steps(toaster: ApplianceModel) -> None:
    goal = {"function": "bake", "temperature": "200 °C", "timer": "45 min", "convection": "on"}
    found = plan(toaster, None, goal)
    compiled = compiled_model(toaster)
    canonical = found.goal
    assert len(found) == shortest_plan_length(compiled, compiled.initial_state(), canonical)
    assert execute(toaster, found).satisfies(canonical)
    setting = next(m for m in found.macro_actions if m.feature == "set_timer")
    assert len(setting.actions) == 17  # 10 one-minute detents, then 7 of five minutes


def test_programme_dependent_setting_needs_its_programme(toaster: ApplianceModel) -> None:
    found = plan(toaster, None, {"toast_shade": 6})
    assert found.macro_actions[0].feature == "select_function"
    assert execute(toaster, found).value("toast_shade") == 6


def test_goal_already_holds(washer: ApplianceModel) -> None:
    assert len(plan(washer, None, {"programme": "cotton"})) == 0


def test_invalid_goal_is_a_goal_error(washer: ApplianceModel) -> None:
    with pytest.raises(GoalError, match="did you mean 'wool'"):
        plan(washer, None, {"programme": "wol"})
    with pytest.raises(GoalError, match="does not exist when programme is 'rinse and spin'"):
        plan(washer, None, {"programme": "rinse and spin", "temperature": "40"})


ONE_WAY = """
controls: [{id: b, label: B}, {id: c, label: C}]
variables:
  level: {type: numeric, ranges: [[0, 5, 1]], initial: 2}
  other: {type: discrete, values: [p, q]}
actions: {press_b: {control: b}, press_c: {control: c}}
features:
  up: [{actions: [press_b], variable: level, effect: next}]
  other: [{actions: [press_c], variable: other, effect: toggle, reset: [level]}]
"""


def test_unreachable_value_gets_a_reason() -> None:
    model = model_from(ONE_WAY.replace("initial: 2", "initial: 2, wrap: false"), check=False)
    sim = Simulator(model)
    for _ in range(3):
        sim.step("press_b")
    with pytest.raises(Unreachable, match=r"level cannot become 1 from 5: .*reach 2, 3, 4, 5"):
        plan(model, sim.state, {"level": 1})
    assert [a.name for a in plan(model, sim.state, {"level": 2}).actions] == ["press_c"]


def test_an_unreachable_value_is_named_as_blocked_whatever_the_guards() -> None:
    model = model_from(ONE_WAY.replace("initial: 2", "initial: 2, wrap: false"), check=False)
    sim = Simulator(model)
    for _ in range(3):
        sim.step("press_b")
    with pytest.raises(Unreachable) as caught:
        plan(model, sim.state, {"level": 1})
    assert caught.value.blocked == ("level",) and not caught.value.budget_hit
    again = caught.value.again()  # the remembered answer, re-raised, says the same
    assert (again.blocked, again.reason) == (("level",), caught.value.reason)
    assert pickle.loads(pickle.dumps(caught.value)).reason == caught.value.reason


def test_the_costly_reason_is_worked_out_only_when_read(monkeypatch: pytest.MonkeyPatch) -> None:
    import apbot.plan.plan as planning

    model = model_from(ONE_WAY.replace("initial: 2", "initial: 2, wrap: false"), check=False)
    sim = Simulator(model)
    for _ in range(3):
        sim.step("press_b")
    walks: list[int] = []
    real = planning._forward_values
    monkeypatch.setattr(
        planning,
        "_forward_values",
        lambda *a: walks.append(1) or real(*a),  # type: ignore
    )
    with pytest.raises(Unreachable) as caught:
        plan(model, sim.state, {"level": 1})
    assert walks == []  # a caller that only tries a guess pays nothing for the words
    assert "reach 2, 3, 4, 5" in str(caught.value) and walks


JOINT = """
controls: [{id: a, label: A}, {id: b, label: B}]
variables:
  door: {type: discrete, values: [closed, open]}
  heat: {type: discrete, values: ["off", "on"]}
actions: {press_a: {control: a}, press_b: {control: b}}
features:
  door: [{actions: [press_a], variable: door, effect: toggle, set: {heat: "off"}}]
  heat: [{actions: [press_b], variable: heat, effect: toggle, set: {door: closed}}]
"""


def test_jointly_impossible_goal_gets_a_reason() -> None:
    model = model_from(JOINT, check=False)
    with pytest.raises(Unreachable, match="hold together") as caught:
        plan(model, None, {"door": "open", "heat": "on"})
    assert caught.value.blocked == ()  # each value alone is reachable


def test_budget_is_reported(washer: ApplianceModel) -> None:
    goal = {"power": "on", "programme": "wool", "temperature": "20", "finish_in": "5 h"}
    with pytest.raises(Unreachable, match="budget"):
        plan(washer, None, goal, budget=1)


def test_a_work_limit_gives_up_on_successors_generated(washer: ApplianceModel) -> None:
    goal = {"power": "on", "programme": "wool", "temperature": "20", "finish_in": "5 h"}
    found = plan(washer, None, goal)
    with pytest.raises(Unreachable, match="successors") as caught:
        plan(washer, None, goal, work=2)
    assert caught.value.budget_hit
    assert len(plan(washer, None, goal, work=1_000_000)) == len(found)


def test_a_longest_plan_wanted_prunes_the_search(washer: ApplianceModel) -> None:
    """``most``: a plan that long is found as before; one press less, there is none, and the
    search says so after expanding fewer states than the full search did."""
    goal = {"power": "on", "programme": "wool", "temperature": "20", "finish_in": "5 h"}
    found = plan(washer, None, goal)
    assert len(plan(washer, None, goal, most=len(found))) == len(found)
    with pytest.raises(Unreachable, match=f"at most {len(found) - 1} actions") as caught:
        plan(washer, None, goal, most=len(found) - 1)
    assert not caught.value.budget_hit
    with pytest.raises(Unreachable, match="at most 0 actions"):
        plan(washer, None, goal, most=0)


PLATEAU = """
controls: [{id: power}, {id: prog}, {id: clock}, {id: eco}]
variables:
  power: {type: discrete, values: ["off", "on"]}
  programme: {type: discrete, values: [cool, heat, dry, auto]}
  clock: {type: time, wrap: true, ranges: [["01:00:00", "12:59:00", 60]]}
  eco: {type: numeric, wrap: true, ranges: [[1, 5, 1]]}
actions: {press_power: {control: power}, press_prog: {control: prog},
          press_clock: {control: clock}, press_eco: {control: eco}}
features:
  power: [{actions: [press_power], variable: power, effect: toggle}]
  set_programme: [{actions: [press_prog], variable: programme, effect: next,
                   reset: [clock, eco]}]
  set_clock: [{actions: [press_clock], variable: clock, effect: next}]
  set_eco: [{actions: [press_eco], variable: eco, effect: next}]
guards:
  - {when: {power: "off"}, only: [press_power]}
"""


def test_settings_a_programme_key_resets_are_planned_without_a_plateau() -> None:
    """The shape of a read air conditioner manual: the programme key resets a 720-value
    clock. Every state that sets the clock before the programme looked as good as the
    optimum to the plain bound, and the search ran out of work; now it walks straight in."""
    model = model_from(PLATEAU)
    goal = {"power": "on", "programme": "heat", "clock": "07:45", "eco": "4"}
    found = plan(model, None, goal, work=100_000)
    assert len(found) == 1 + 1 + 405 + 3
    assert found.expanded < 50
    assert execute(model, found).satisfies(found.goal)


CLOCK = """
controls: [{id: clock, label: CLOCK}, {id: hour, label: HOUR}, {id: minute, label: MIN}]
variables:
  clock: {type: time, wrap: true, ranges: [["00:00:00", "23:59:00", 60]], initial: "06:00:00"}
actions: {press_clock: {control: clock}, press_hour: {control: hour},
          press_min: {control: minute}}
features:
  set_clock:
    - {actions: [press_clock]}
    - {actions: [press_hour, press_min], variable: clock,
       effect: {press_hour: {add: 3600}, press_min: {add: 60}}}
"""


@pytest.mark.parametrize("goal", ["07:45", "05:59", "23:59", "12:30"])
def test_large_domain_visits_keep_the_goal(goal: str) -> None:
    """A 1440-value clock: pruning a visit's exits must never drop the goal itself."""
    model = model_from(CLOCK)
    compiled = compiled_model(model)
    canonical = {"clock": f"{goal}:00"}
    shortest = shortest_plan_length(compiled, compiled.initial_state(), canonical)
    assert len(plan(model, None, canonical)) == shortest


PROGRAMME_SHORTCUT = """
controls: [{id: p, label: PROG}, {id: s, label: SET}, {id: l, label: LEVEL}, {id: o, label: "OFF"}]
variables:
  prog: {type: discrete, values: [a, b, c]}
  setting: {type: discrete, depends_on: prog,
            cases: {a: {values: [x1, x2, x3, x4, x5], initial: x1},
                    b: {values: [x1, x2, x3, x4, x5], initial: x5},
                    c: {values: [x1, x5], initial: x1}}}
  level: {type: numeric, ranges: [[0, 3, 1]]}
actions: {press_prog: {control: p}, press_set: {control: s}, press_level: {control: l},
          press_off: {control: o}}
features:
  prog: [{actions: [press_prog], variable: prog, effect: next}]
  setting: [{actions: [press_set], variable: setting, effect: next}]
  level: [{actions: [press_level], variable: level, effect: next}]
  switch_off: [{actions: [press_off], reset: [prog, level]}]
"""


@pytest.mark.parametrize(
    "goal",
    [
        {"setting": "x5"},
        {"setting": "x5", "level": 3},
        {"setting": "x2", "level": 2},
        {"setting": "x1", "level": 1},
    ],
)
def test_a_programme_change_as_a_shortcut_to_a_setting(goal: dict[str, object]) -> None:
    """The setting's goal is some programme's default; the programme is not in the goal."""
    model = model_from(PROGRAMME_SHORTCUT)
    compiled = compiled_model(model)
    start = Simulator(model)
    start.step("press_set")
    for state in (compiled.initial_state(), start.state):
        found = plan(model, state, goal)
        assert len(found) == shortest_plan_length(compiled, state, found.goal)


def test_among_equally_short_plans_the_display_is_lit_while_setting() -> None:
    """A knob that also turns while the appliance is off: set it after switching on, where the
    display shows it (the closed loop can only check what it can see)."""
    model = model_from("""
        controls: [{id: power, label: POWER}, {id: knob, kind: dial, label: MODE}]
        variables:
          power: {type: discrete, values: ["off", "on"]}
          mode: {type: discrete, values: [a, b, c]}
        actions:
          press_power: {control: power}
          turn_knob: {control: knob, skill: turn_cw}
        features:
          power: [{actions: [press_power], variable: power, effect: toggle}]
          mode: [{actions: [turn_knob], variable: mode, effect: next}]
        guards:
          - {when: {power: "off"}, only: [press_power, turn_knob], display: "", hide: true}
    """)
    found = plan(model, None, {"power": "on", "mode": "c"})
    assert [a.name for a in found.actions] == ["press_power", "turn_knob", "turn_knob"]


def test_bad_arguments_name_themselves(washer: ApplianceModel) -> None:
    goal = {"power": "on"}
    with pytest.raises(TypeError, match="plan needs an ApplianceModel"):
        plan(None, None, goal)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"state must be a State .* not str"):
        plan(washer, "junk", goal)  # type: ignore[arg-type]
    start = compiled_model(washer).initial_state()
    with pytest.raises(ValueError, match=r"state\.values must hold one value index for each"):
        plan(washer, start._replace(values=start.values[:2]), goal)
    with pytest.raises(TypeError, match=r"not str 'power=on'"):
        plan(washer, None, "power=on")  # type: ignore[arg-type]
    with pytest.raises(GoalError, match="is not NAME=VALUE"):
        plan(washer, None, [42])  # type: ignore[list-item]
    with pytest.raises(ValueError, match="budget is a positive number"):
        plan(washer, None, goal, budget=0)
    with pytest.raises(ValueError, match="work is a positive number"):
        plan(washer, None, goal, work=0)
    with pytest.raises(ValueError, match="most is a number of actions"):
        plan(washer, None, goal, most=-1)
    assert len(plan(washer, start, goal)) == 1  # a real state is fine


def test_a_goal_on_a_value_declared_unreachable_says_so() -> None:
    model = model_from(
        """
        controls: [{id: start_button, label: START}, {id: stop_button, label: STOP}]
        variables:
          stage: {type: discrete, values: [idle, drying, cooling], unreachable: [cooling]}
        actions: {press_start: {control: start_button}, press_stop: {control: stop_button}}
        features:
          start: [{actions: [press_start], variable: stage, effect: {to: drying}}]
          stop: [{actions: [press_stop], variable: stage, effect: {to: idle}}]
        """
    )
    compiled = compiled_model(model)
    assert shortest_plan_length(compiled, compiled.initial_state(), {"stage": "cooling"}) is None
    with pytest.raises(Unreachable, match=r"stage cannot become 'cooling': .*declares it unreach"):
        plan(model, None, {"stage": "cooling"})
    assert len(plan(model, None, {"stage": "drying"})) == 1


def test_unreachable_says_why_in_its_repr() -> None:
    assert repr(Unreachable("no key sets it")) == "Unreachable('no key sets it')"
    lazy = Unreachable(lambda: "worked out later")
    assert "cannot be reached" in repr(lazy)
    assert str(lazy) == "worked out later"
