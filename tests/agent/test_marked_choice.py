"""A knob that only highlights a programme while it turns (``PICK glass``) and takes it when
pushed (``GLASS``): the agent looks at the highlighted choice at once — the push the look
makes takes it, before the settings the choice resets are set — and never claims a
programme the appliance did not take."""

from __future__ import annotations

from apbot.agent.marked import letter_case, marked_now
from tests.helpers import model_from
from tests.helpers import run_checked as run

TRUTH = """
controls: [{id: power, label: POWER}, {id: knob, kind: knob, label: PROGRAMME},
           {id: extra, label: EXTRA}, {id: go, label: GO}]
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": ECO}}
  pick: {type: discrete, values: [eco, intensive, glass, rinse], label: PICK}
  programme:
    type: discrete
    values: [eco, intensive, glass, rinse]
    show: {eco: ECO, intensive: INTENSIVE, glass: GLASS, rinse: RINSE}
  extra: {type: numeric, unit: min, ranges: [[0, 30, 10]], wrap: true, label: EXTRA}
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "GO"}}
actions:
  press_power: {control: power}
  turn_cw: {control: knob, skill: turn_cw}
  turn_ccw: {control: knob, skill: turn_ccw}
  push_knob: {control: knob}
  press_extra: {control: extra}
  press_go: {control: go}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle, reset: [pick, programme]}
  pick:
    - {actions: [turn_cw, turn_ccw], variable: pick, effect: {turn_cw: next, turn_ccw: prev}}
  take:
    - actions: [push_knob]
      variable: programme
      reset: [extra]
      effect:
        when: {pick: eco}
        then: {to: eco}
        otherwise:
          when: {pick: intensive}
          then: {to: intensive}
          otherwise:
            when: {pick: glass}
            then: {to: glass}
            otherwise: {to: rinse}
  extra:
    - {actions: [press_extra], variable: extra, effect: next}
  go:
    - {actions: [press_go], variable: running, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
  - {name: running, when: {running: "on"}, only: [press_go, press_power], display: GO}
display:
  idle: "{programme}"
  indicators: [running]
"""

# what a reader makes of "turn the knob to choose the programme": the turns set it; the
# manual's legend gave it the word PICK, as the sign of running
BELIEF = """
controls: [{id: power, label: POWER}, {id: knob, kind: knob, label: PROGRAMME},
           {id: extra, label: EXTRA}, {id: go, label: GO}]
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "{programme}"}}
  programme: {type: discrete, values: [eco, intensive, glass, rinse], label: PROGRAMME}
  extra: {type: numeric, unit: min, ranges: [[0, 30, 10]], wrap: true, label: EXTRA}
  running: {type: discrete, values: ["off", "on"], show: {"off": "", "on": PICK}}
actions:
  press_power: {control: power}
  turn_cw: {control: knob, skill: turn_cw}
  turn_ccw: {control: knob, skill: turn_ccw}
  push_knob: {control: knob}
  press_extra: {control: extra}
  press_go: {control: go}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  programme:
    - {actions: [turn_cw, turn_ccw], variable: programme,
       effect: {turn_cw: next, turn_ccw: prev}}
  knob_push:
    - {actions: [push_knob]}
    - {actions: [turn_cw, turn_ccw], variable: programme,
       effect: {turn_cw: next, turn_ccw: prev}}
  extra:
    - {actions: [press_extra], variable: extra, effect: next}
  go:
    - {actions: [press_go], variable: running, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], hide: true}
  - {name: running, when: {running: "on"}, only: [press_go, press_power]}
display:
  idle: "{programme}"
"""


def test_a_highlighted_choice_is_taken_before_the_settings_it_resets() -> None:
    """Turned to ``PICK glass`` (the home screen printed ``ECO``), the programme is looked at
    at once; the look's push takes it and resets the extra time, which is set after it. Without
    the rule the run claims glass with the appliance still on eco."""
    episode, reached = run(
        model_from(TRUTH), model_from(BELIEF), {"programme": "glass", "extra": 20, "running": "on"}
    )
    assert reached
    assert any(e.action == "push_knob" for e in episode.trace)


def test_only_a_partial_reading_in_another_letter_case_marks_a_choice() -> None:
    belief = model_from(BELIEF)
    forms: dict[str, str] = {}
    marked: set[str] = set()
    marked_now(belief, {"programme": "eco"}, "ECO", False, forms, marked)
    assert forms == {"programme": "upper"} and not marked
    marked_now(belief, {"programme": "intensive"}, "PICK INTENSIVE", True, forms, marked)
    assert not marked  # the same capitals: a label the belief lacks, no highlight
    marked_now(belief, {"programme": "glass"}, "PICK glass", True, forms, marked)
    assert marked == {"programme"}
    marked_now(belief, {"programme": "glass"}, "GLASS", False, forms, marked)
    assert not marked
    assert letter_case(belief, "extra", 20, "EXTRA 20 min") is None  # no word value
