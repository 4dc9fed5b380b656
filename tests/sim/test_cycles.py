"""Cycles that end by themselves: only waiting lets time pass, a press takes none, a cycle
stopped and started again counts from zero, and the end's side effects apply as a step's."""

from __future__ import annotations

import pytest

from apbot.model.problems import ModelError
from apbot.sim.simulator import Simulator
from apbot.testing.bfs import compare_with_bfs
from tests.helpers import model_from

OVEN = """
controls: [{id: start, label: START}, {id: up, label: "+1 MIN"}]
variables:
  cook_time: {type: time, ranges: [["00:00:00", "00:05:00", 60]], format: "mm:ss"}
  running: {type: discrete, values: ["off", "on"]}
actions:
  press_start: {control: start}
  press_up: {control: up}
features:
  add_minute: [{actions: [press_up], variable: cook_time, effect: {add: 60}}]
  start: [{actions: [press_start], variable: running, effect: toggle}]
guards:
  - {name: running, when: {running: "on"}, only: [press_start], display: RUN}
cycles:
  - name: cooking
    when: {running: "on"}
    lasts: cook_time
    set: {running: "off"}
    reset: [cook_time]
"""


def test_a_cycle_ends_after_its_time_and_only_by_waiting() -> None:
    sim = Simulator(model_from(OVEN))
    for action in ["press_up", "press_up", "press_start"]:
        sim.step(action)
    assert sim.wait(119).values["running"] == "on"
    assert sim.assignment() == {"cook_time": "00:02:00", "running": "on"}
    sim.wait(1)
    assert sim.assignment() == {"cook_time": "00:00:00", "running": "off"}


def test_pausing_restarts_the_clock_and_waiting_idle_changes_nothing() -> None:
    sim = Simulator(model_from(OVEN))
    sim.wait(500)  # nothing runs
    assert sim.assignment() == {"cook_time": "00:00:00", "running": "off"}
    for action in ["press_up", "press_start"]:
        sim.step(action)
    sim.wait(50)
    sim.step("press_start")  # pause
    sim.step("press_start")  # and start again: a full minute from now
    sim.wait(50)
    assert sim.value("running") == "on"
    sim.wait(10)
    assert sim.value("running") == "off"
    with pytest.raises(ValueError, match="seconds must be a finite number above zero"):
        sim.wait(-1)


def test_the_planner_plans_presses_while_no_time_passes() -> None:
    model = model_from(OVEN)
    assert compare_with_bfs(model, {"cook_time": "00:03:00", "running": "on"}) == (4, 4)


def test_cycles_are_checked() -> None:
    with pytest.raises(ModelError, match="cannot say how long the cycle lasts"):
        model_from(OVEN.replace("lasts: cook_time", "lasts: running"))
    with pytest.raises(ModelError, match="unknown variable 'runing'"):
        model_from(OVEN.replace('set: {running: "off"}', 'set: {runing: "off"}'))
    with pytest.raises(ModelError, match="a cycle's end changes nothing"):
        model_from(OVEN.replace('    set: {running: "off"}\n    reset: [cook_time]\n', ""))
