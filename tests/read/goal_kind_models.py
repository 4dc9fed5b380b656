"""Two small models written for the goal-parser tests of kinds of saying a setting (a seedling
grow light with a heat mat, a rowing machine), shared by the tests that use them as fixtures."""

from __future__ import annotations

GROW_LIGHT = """
appliance: {id: grow_1, category: grow_light, name: "Sprout S1 seedling light", brand: S}
controls:
  - {id: set_button, kind: button, label: "SET"}
  - {id: on_button, kind: button, label: "ON TIME"}
  - {id: off_button, kind: button, label: "OFF TIME"}
  - {id: up_button, kind: button, label: "+"}
  - {id: down_button, kind: button, label: "-"}
  - {id: level_button, kind: button, label: "LEVEL"}
  - {id: mat_button, kind: button, label: "MAT"}
  - {id: soak_button, kind: button, label: "SOAK"}
variables:
  clock:
    type: time
    ranges: [["00:00:00", "23:59:00", 60]]
    initial: "12:00:00"
    wrap: true
    label: "CLOCK"
  on_time:
    type: time
    ranges: [["00:00:00", "23:30:00", 1800]]
    initial: "07:00:00"
    wrap: true
    label: "ON TIME"
  off_time:
    type: time
    ranges: [["00:00:00", "23:30:00", 1800]]
    initial: "19:00:00"
    wrap: true
    label: "OFF TIME"
  level:
    type: discrete
    values: ["25", "50", "75", "100"]
    show: {"25": "▮▯▯▯", "50": "▮▮▯▯", "75": "▮▮▮▯", "100": "▮▮▮▮"}
  mat:
    type: numeric
    unit: "°C"
    ranges: [[20, 32, 1]]
    initial: 24
    label: "MAT"
  soak:
    type: numeric
    unit: min
    ranges: [[5, 40, 5]]
    initial: 10
    label: "SOAK"
actions:
  press_set: {control: set_button}
  press_on: {control: on_button}
  press_off: {control: off_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_level: {control: level_button}
  press_mat: {control: mat_button}
  press_soak: {control: soak_button}
features:
  clock:
    - {actions: [press_set]}
    - actions: [press_up, press_down]
      variable: clock
      effect: {press_up: next, press_down: prev}
  on_time:
    - {actions: [press_on]}
    - actions: [press_up, press_down]
      variable: on_time
      effect: {press_up: next, press_down: prev}
  off_time:
    - {actions: [press_off]}
    - actions: [press_up, press_down]
      variable: off_time
      effect: {press_up: next, press_down: prev}
  level:
    - {actions: [press_level], variable: level, effect: next}
  mat:
    - {actions: [press_mat]}
    - actions: [press_up, press_down]
      variable: mat
      effect: {press_up: next, press_down: prev}
  soak:
    - {actions: [press_soak]}
    - actions: [press_up, press_down]
      variable: soak
      effect: {press_up: next, press_down: prev}
display:
  idle: "{clock}"
  indicators: [level]
"""

ROWER = """
appliance: {id: rower_1, category: rowing_machine, name: "Glide R3 rowing machine", brand: G}
controls:
  - {id: goal_button, kind: button, label: "GOAL"}
  - {id: up_button, kind: button, label: "▲"}
  - {id: down_button, kind: button, label: "▼"}
  - {id: drag_button, kind: button, label: "DRAG"}
variables:
  goal_kind:
    type: discrete
    values: [time, distance, calories]
    show: {time: "TIME", distance: "DIST", calories: "ENERGY"}
  goal:
    type: numeric
    depends_on: goal_kind
    cases:
      time: {ranges: [[5, 90, 5]], initial: 20}
      distance: {ranges: [[1, 30, 1]], initial: 2}
      calories: {ranges: [[50, 1500, 50]], initial: 200}
    show: "{value}"
  drag:
    type: numeric
    ranges: [[1, 8, 1]]
    initial: 4
    wrap: true
    label: "DRAG"
actions:
  press_goal: {control: goal_button}
  press_up: {control: up_button}
  press_down: {control: down_button}
  press_drag: {control: drag_button}
features:
  goal_kind:
    - {actions: [press_goal], variable: goal_kind, effect: next}
  goal:
    - actions: [press_up, press_down]
      variable: goal
      effect: {press_up: next, press_down: prev}
  drag:
    - {actions: [press_drag], variable: drag, effect: next}
display:
  idle: "{goal}"
  indicators: [goal_kind]
"""
