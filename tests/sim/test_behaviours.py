"""The behaviours added to the format for real manuals, run on the simulator, checked, and
planned exactly: hold-to-scroll (``skip``), effects that depend on the state, guards for one
dial position (``other_than``), values no key reaches."""

from __future__ import annotations

import pytest

from apbot.model.problems import ModelError
from apbot.model.validate import check_model
from apbot.sim.compiled import compiled_model
from apbot.sim.simulator import Simulator
from apbot.testing.bfs import compare_with_bfs
from tests.helpers import model_from

SCROLL = """
controls: [{id: up, label: UP}, {id: down, label: DOWN}]
variables:
  level: {type: numeric, ranges: [[0, 20, 1]], wrap: WRAP}
actions:
  press_up: {control: up}
  hold_up: {control: up, skill: hold, seconds: 2}
  hold_down: {control: down, skill: hold, seconds: 2}
features:
  level:
    - actions: [press_up, hold_up, hold_down]
      variable: level
      effect: {press_up: next, hold_up: {skip: 5}, hold_down: {skip: -3}}
"""

PLUS30 = """
controls: [{id: start, label: "START/+30s"}, {id: up, label: "+1 MIN"}, {id: stop, label: STOP}]
variables:
  cook_time: {type: time, ranges: [["00:00:00", "00:05:00", 30]], format: "mm:ss"}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_start: {control: start}
  press_up: {control: up}
  press_stop: {control: stop}
features:
  add_minute: [{actions: [press_up], variable: cook_time, effect: {add: 60}}]
  start:
    - actions: [press_start]
      variable: cook_time
      effect:
        when: {running: "on"}
        then: {add: 30}
        otherwise: {when: {cook_time: "00:00:00"}, then: {add: 30}, otherwise: none}
      set: {running: "on"}
  stop: [{actions: [press_stop], variable: running, effect: {to: "off"}, reset: [cook_time]}]
guards:
  - {name: running, when: {running: "on"}, only: [press_start, press_stop], display: RUN}
"""


@pytest.mark.parametrize(
    ("wrap", "after"), [("false", [5, 10, 15, 20, 20, 17]), ("true", [5, 10, 15, 20, 4, 1])]
)
def test_a_held_key_skips_several_values(wrap: str, after: list[int]) -> None:
    sim = Simulator(model_from(SCROLL.replace("WRAP", wrap)))
    seen = [sim.step(a).values["level"] for a in ["hold_up"] * 5 + ["hold_down"]]
    assert seen == after
    assert sim.step("hold_up", seconds=1).accepted is False  # a short hold is no hold


def test_holding_is_planned_when_it_is_shorter() -> None:
    model = model_from(SCROLL.replace("WRAP", "false"))
    for goal in ({"level": 12}, {"level": 19}, {"level": 3}):
        found, shortest = compare_with_bfs(model, goal)
        assert found == shortest and found is not None
    assert compare_with_bfs(model, {"level": 12}) == (4, 4)  # hold, hold, up, up


def test_a_conditional_effect_picks_its_branch_on_the_state_before_the_press() -> None:
    sim = Simulator(model_from(PLUS30))
    assert sim.step("press_start").values == {"cook_time": "00:00:30"}  # nothing set: +30 s
    assert sim.value("running") == "on"
    assert sim.step("press_start").values == {"cook_time": "00:01:00"}  # running: +30 s
    sim.step("press_stop")
    sim.step("press_up")
    assert sim.step("press_start").values == {"cook_time": "00:01:00"}  # a time set: start
    assert sim.value("running") == "on"


def test_conditional_effects_are_planned_exactly() -> None:
    model = model_from(PLUS30)
    compiled = compiled_model(model)
    goals = [
        {"cook_time": "00:01:30", "running": "on"},
        {"cook_time": "00:02:00", "running": "on"},
        {"cook_time": "00:02:00", "running": "off"},
        {"cook_time": "00:05:00", "running": "on"},
    ]
    for goal in goals:
        found, shortest = compare_with_bfs(model, goal)
        assert found == shortest, goal
    # the planner's projection keeps what the conditions read
    assert {compiled.vars[v].name for v in compiled.influencers({0})} == {"cook_time", "running"}


def test_conditional_effects_are_checked() -> None:
    bad_value = PLUS30.replace('when: {running: "on"}\n', "when: {running: maybe}\n")
    problems = [p for p in check_model(model_from(bad_value, check=False)) if p.severity == "error"]
    assert [(p.where, p.message) for p in problems] == [
        (
            "features.start[0].effect.when.running",
            "'maybe' is not a value of 'running' (['off', 'on'])",
        )
    ]
    unknown = PLUS30.replace('when: {running: "on"}\n', 'when: {runing: "on"}\n')
    with pytest.raises(ModelError, match="unknown variable 'runing'; did you mean 'running'"):
        model_from(unknown)
    typed = PLUS30.replace(
        "then: {add: 30}\n        otherwise: {when", "then: digit\n        otherwise: {when"
    )
    with pytest.raises(ModelError, match="digit belongs to a keypad step"):
        model_from(typed)


def test_a_guard_for_one_dial_position() -> None:
    text = """
    controls: [{id: dial, kind: dial, label: MODE}, {id: plus, label: "+"}]
    variables:
      mode: {type: discrete, values: ["off", toast, timer], wrap: false}
      minutes: {type: numeric, ranges: [[0, 30, 5]]}
    actions:
      turn_cw: {control: dial, skill: turn_cw}
      turn_ccw: {control: dial, skill: turn_ccw}
      press_plus: {control: plus}
    features:
      mode:
        - {actions: [turn_cw, turn_ccw], variable: mode, effect: {turn_cw: next, turn_ccw: prev}}
      minutes: [{actions: [press_plus], variable: minutes, effect: next}]
    guards:
      - {when: {mode: {other_than: timer}}, only: [turn_cw, turn_ccw]}
    """
    model = model_from(text)
    sim = Simulator(model)
    assert [sim.step(a).accepted for a in ["press_plus", "turn_cw", "press_plus"]] == [
        False,
        True,
        False,
    ]
    assert [sim.step(a).accepted for a in ["turn_cw", "press_plus"]] == [True, True]
    assert compare_with_bfs(model, {"minutes": 10, "mode": "toast"}) == (5, 5)
    wrong = text.replace("{other_than: timer}", "{other_than: grill}")
    with pytest.raises(ModelError, match="'grill' is not a value of 'mode'"):
        model_from(wrong)


WASHER = """
controls:
  - {id: prog, label: PROGRAMME}
  - {id: temp, label: TEMP}
  - {id: power, label: POWER}
  - {id: cotton_key, label: COTTON}
variables:
  power: {type: discrete, values: ["off", "on"]}
  programme: {type: discrete, values: [cotton, synthetics, wool]}
  temperature:
    type: discrete
    depends_on: programme
    remember: REMEMBER
    cases:
      cotton: {values: ["30", "40", "60"], initial: "40"}
      synthetics: ["30", "40"]
actions:
  press_power: {control: power}
  press_programme: {control: prog}
  press_temp: {control: temp}
  press_cotton: {control: cotton_key}
features:
  power: [{actions: [press_power], variable: power, effect: toggle, reset: [temperature]}]
  programme: [{actions: [press_programme], variable: programme, effect: next}]
  cotton: [{actions: [press_cotton], variable: programme, effect: {to: cotton}}]
  temperature: [{actions: [press_temp], variable: temperature, effect: next}]
guards:
  - {when: {power: "off"}, only: [press_power], display: "", hide: true}
"""


def _temperatures(remember: str, presses: list[str]) -> list[str | None]:
    sim = Simulator(model_from(WASHER.replace("REMEMBER", remember)))
    seen = []
    for action in presses:
        assert sim.step(action).accepted, action
        seen.append(sim.value("temperature"))
    return seen


def test_a_remembered_setting_keeps_its_value_per_programme() -> None:
    presses = ["press_power", "press_temp", "press_programme", "press_temp"]
    presses += ["press_programme", "press_programme", "press_programme", "press_cotton"]
    # cotton 60, synthetics 40, wool has none; back round: cotton 60, synthetics 40, cotton 60
    assert _temperatures("true", presses) == ["40", "60", "30", "40", None, "60", "40", "60"]
    assert _temperatures("false", presses) == ["40", "60", "30", "40", None, "40", "30", "40"]


def test_a_reset_forgets_every_programmes_value() -> None:
    presses = ["press_power", "press_temp", "press_programme", "press_temp", "press_power"]
    presses += ["press_power", "press_programme", "press_programme"]
    # switching off resets the temperature: cotton's 60 and synthetics' 40 are forgotten
    assert _temperatures("true", presses)[-3:] == ["30", None, "40"]


def test_remembered_settings_are_planned_exactly_from_every_state() -> None:
    from apbot.model.goal import parse_goal
    from apbot.testing.bfs import bound_violations, distances_to_goal, planner_mismatches

    model = model_from(WASHER.replace("REMEMBER", "true"))
    compiled = compiled_model(model)
    for goal in (
        {"temperature": "60"},
        {"temperature": "30", "programme": "synthetics"},
        {"temperature": "60", "power": "off"},
        {"programme": "cotton", "temperature": "30"},
    ):
        canonical = parse_goal(model, goal)
        states, distance = distances_to_goal(compiled, canonical)
        assert len({s.memory for s in states}) > 1  # the kept values are part of the state
        assert planner_mismatches(compiled, canonical, states, distance) == [], goal
        assert bound_violations(compiled, canonical, states, distance) == [], goal


def test_remember_needs_a_programme_and_states_keep_it_consistent() -> None:
    text = BAD_REMEMBER
    with pytest.raises(ModelError, match="`remember` keeps a value per programme"):
        model_from(text)
    compiled = compiled_model(model_from(WASHER.replace("REMEMBER", "true")))
    state = compiled.initial_state()
    assert state.memory == (1, 0)  # cotton's default 40, synthetics' 30
    with pytest.raises(ValueError, match="memory must hold 2 kept values"):
        compiled.check_state(state._replace(memory=()))
    with pytest.raises(ValueError, match="keeps 2 for temperature in the current programme"):
        compiled.check_state(state._replace(memory=(2, 0)))


BAD_REMEMBER = """
controls: [{id: b, label: UP}]
variables:
  level: {type: numeric, ranges: [[0, 3, 1]], remember: true}
actions: {press_up: {control: b}}
features:
  level: [{actions: [press_up], variable: level, effect: next}]
"""
