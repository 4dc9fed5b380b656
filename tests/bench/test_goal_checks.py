"""Goals that an obviously different operation meets are found, and only those."""

from __future__ import annotations

from apbot.bench.goal_checks import goal_findings
from apbot.bench.suite import bundled_suite_dir, load_appliance
from apbot.model.goal import parse_goal
from apbot.model.schema import ApplianceModel
from apbot.sim.simulator import Simulator
from tests.helpers import model_from

DIGITS = "[press_0, press_1, press_2, press_3]"


def _microwave(express_drops_defrost: bool) -> ApplianceModel:
    """A keypad microwave: DEFROST + digits + START, and express pads that cook and start."""
    reset = "[defrost_time]" if express_drops_defrost else "[]"
    return model_from(
        f"""
        controls:
          - {{id: defrost_pad, kind: touch, label: DEFROST}}
          - {{id: start_pad, kind: touch, label: START}}
          - {{id: key_0, kind: key, label: "0"}}
          - {{id: key_1, kind: key, label: "1"}}
          - {{id: key_2, kind: key, label: "2"}}
          - {{id: key_3, kind: key, label: "3"}}
          - {{id: express_1, kind: touch, label: "1 MIN"}}
          - {{id: express_2, kind: touch, label: "2 MIN"}}
        variables:
          cook_time: {{type: time, ranges: [["00:00:00", "00:02:00", 60]], initial: "00:00:00"}}
          defrost_time:
            type: time
            ranges: [["00:00:00", "00:30:00", 60]]
            initial: "00:00:00"
            format: "mm:ss"
            entry: {{format: "mm:ss"}}
          running: {{type: discrete, values: ["off", "on"]}}
        actions:
          press_defrost: {{control: defrost_pad}}
          press_start: {{control: start_pad}}
          press_0: {{control: key_0, digit: 0}}
          press_1: {{control: key_1, digit: 1}}
          press_2: {{control: key_2, digit: 2}}
          press_3: {{control: key_3, digit: 3}}
          press_x1: {{control: express_1}}
          press_x2: {{control: express_2}}
        features:
          defrost:
            - {{actions: [press_defrost]}}
            - {{actions: {DIGITS}, variable: defrost_time}}
          express:
            - actions: [press_x1, press_x2]
              variable: cook_time
              effect:
                press_x1: {{to: "00:01:00"}}
                press_x2: {{to: "00:02:00"}}
              set: {{running: "on"}}
              reset: {reset}
          start:
            - {{actions: [press_start], variable: running, effect: {{to: "on"}}}}
        """
    )


def _keys(model: ApplianceModel, goal: dict[str, str]) -> list[str]:
    return [f.key for f in goal_findings(model, parse_goal(model, goal))]


def test_an_express_key_that_runs_a_cook_is_flagged_for_a_defrost_goal() -> None:
    goal = {"defrost_time": "2 min", "running": "on"}
    findings = goal_findings(_microwave(False), parse_goal(_microwave(False), goal))
    assert [f.key for f in findings] == ["quick-start"]
    assert "cook_time=00:01:00" in findings[0].message
    assert _keys(_microwave(True), goal) == []


def test_start_only_when_the_settings_are_the_defaults() -> None:
    model = model_from(
        """
        controls:
          - {id: mode_button, kind: button, label: MODE}
          - {id: start_button, kind: button, label: START}
        variables:
          mode: {type: discrete, values: ["off", auto, dry], initial: auto}
          running: {type: discrete, values: ["off", "on"]}
        actions:
          press_mode: {control: mode_button}
          press_start: {control: start_button}
        features:
          mode:
            - {actions: [press_mode], variable: mode, effect: next}
          start:
            - {actions: [press_start], variable: running, effect: {to: "on"}}
        guards:
          - {when: {mode: "off"}, only: [press_mode], display: ""}
        """
    )
    assert _keys(model, {"mode": "auto", "running": "on"}) == ["start-only", "free:mode"]
    assert _keys(model, {"mode": "dry", "running": "on"}) == []


def test_a_programme_that_must_be_chosen_before_start_is_a_real_setting() -> None:
    """From OFF, START needs a programme; the first one reached is not thereby free."""
    model = model_from(
        """
        controls:
          - {id: mode_button, kind: button, label: MODE}
          - {id: start_button, kind: button, label: START}
        variables:
          mode: {type: discrete, values: ["off", auto, dry]}
          running: {type: discrete, values: ["off", "on"]}
        actions:
          press_mode: {control: mode_button}
          press_start: {control: start_button}
        features:
          mode:
            - {actions: [press_mode], variable: mode, effect: next}
          start:
            - {actions: [press_start], variable: running, effect: {to: "on"}}
        guards:
          - {when: {mode: "off"}, only: [press_mode], display: ""}
        """
    )
    assert _keys(model, {"mode": "auto", "running": "on"}) == []


def test_free_finds_initial_values_and_a_programmes_own_defaults() -> None:
    model = model_from(
        """
        controls:
          - {id: prog_button, kind: button, label: PROG}
          - {id: temp_button, kind: button, label: TEMP}
          - {id: start_button, kind: button, label: START}
        variables:
          programme: {type: discrete, values: [cotton, wool], initial: cotton}
          temperature:
            type: discrete
            depends_on: programme
            cases:
              cotton: {values: ["40", "60"], initial: "40"}
              wool: {values: ["20", "30"], initial: "30"}
          running: {type: discrete, values: ["off", "on"]}
        actions:
          press_prog: {control: prog_button}
          press_temp: {control: temp_button}
          press_start: {control: start_button}
        features:
          programme:
            - {actions: [press_prog], variable: programme, effect: next}
          temperature:
            - {actions: [press_temp], variable: temperature, effect: next}
          start:
            - {actions: [press_start], variable: running, effect: {to: "on"}}
        """
    )
    assert _keys(model, {"programme": "cotton", "temperature": "60"}) == ["free:programme"]
    assert _keys(model, {"programme": "wool", "temperature": "30"}) == ["free:temperature"]
    assert _keys(model, {"programme": "wool", "temperature": "20"}) == []
    assert _keys(model, {"temperature": "60", "running": "off"}) == ["free:running"]


def test_the_bundled_microwave_1_t03_is_no_longer_met_by_an_express_cook() -> None:
    """The issue's case: defrost entered, clock confirmed with START, then express pad 1."""
    appliance = load_appliance(bundled_suite_dir() / "microwave_1")
    task = next(t for t in appliance.tasks if t.id == "t03")
    goal = parse_goal(appliance.model, task.goal)
    simulator = Simulator(appliance.model)
    presses = ["press_time_defrost", "press_8", "press_3", "press_0"]
    presses += ["press_timer", "press_1", "press_5", "press_0", "press_0", "press_start"]
    presses += ["press_clock", "press_5", "press_5", "press_0", "press_start", "press_1"]
    for press in presses:
        assert simulator.step(press).accepted, press
    assert simulator.value("running") == "on" and simulator.value("cook_time") == "00:01:00"
    assert not simulator.satisfies(goal)
    assert goal_findings(appliance.model, goal) == []
