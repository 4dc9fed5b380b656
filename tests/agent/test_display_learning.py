"""The closed loop learns how the panel prints a setting when the read belief prints it
otherwise: a bare number where the belief adds its unit, a bare time where it adds a label.

Small appliances written for these tests; the belief differs from the truth only in its display
rules (and, for the clock, in the time it believes the clock shows).
"""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

DRYER_TRUTH = """
controls: [{id: up, label: UP}, {id: down, label: DOWN}]
variables:
  target:
    type: discrete
    values: ["CO", "30", "35", "40", "45", "50", "55", "60", "65", "70", "75", "80"]
    initial: "50"
    show: "{value}"
actions: {press_up: {control: up}, press_down: {control: down}}
features:
  set_target:
    - {actions: [press_up, press_down], variable: target,
       effect: {press_up: next, press_down: prev}}
display: {idle: "{target}"}
"""

DRYER_BELIEF = """
controls: [{id: up, label: UP}, {id: down, label: DOWN}]
variables:
  target: {type: numeric, ranges: [[45, 55, 5]], unit: "%", label: TARGET}
actions: {press_up: {control: up}, press_down: {control: down}}
features:
  set_target:
    - {actions: [press_up, press_down], variable: target,
       effect: {press_up: next, press_down: prev}}
"""


def test_a_number_the_panel_prints_without_the_unit_the_belief_gives_it() -> None:
    # the panel shows "45" where the belief prints "TARGET 45%" (and knows a narrower range):
    # the walk's texts read as values once the unit is left out
    episode, reached = run(model_from(DRYER_TRUTH), model_from(DRYER_BELIEF), {"target": 45})
    assert reached and episode.claimed_success
    assert any(r.startswith("target is shown as '{value}'") for r in episode.repairs)


OVEN = """
controls: [{id: clock, label: CLOCK}, {id: start, label: START}, {id: k1, kind: key},
           {id: k2, kind: key}, {id: k3, kind: key}, {id: k4, kind: key}, {id: k5, kind: key},
           {id: k6, kind: key}, {id: k7, kind: key}, {id: k8, kind: key}, {id: k9, kind: key},
           {id: k0, kind: key}]
variables:
  clock:
    type: time
    ranges: [["01:00:00", "12:59:00", 60]]
    initial: "{initial}"
    format: "h:mm"
    entry: {format: "h:mm", max_digits: 4}
    {show}
actions:
  press_clock: {control: clock}
  press_start: {control: start}
  press_1: {control: k1, digit: 1}
  press_2: {control: k2, digit: 2}
  press_3: {control: k3, digit: 3}
  press_4: {control: k4, digit: 4}
  press_5: {control: k5, digit: 5}
  press_6: {control: k6, digit: 6}
  press_7: {control: k7, digit: 7}
  press_8: {control: k8, digit: 8}
  press_9: {control: k9, digit: 9}
  press_0: {control: k0, digit: 0}
features:
  set_clock:
    - {actions: [press_clock]}
    - actions: [press_0, press_1, press_2, press_3, press_4, press_5, press_6, press_7, press_8,
                press_9]
      variable: clock
    - {actions: [press_start]}
"""


def test_a_clock_the_panel_prints_bare_while_digits_are_typed() -> None:
    # the panel keeps showing "12:00" while the digits typed are no time yet; the belief
    # prints the clock as "CLOCK 1:00" and believes it at 1:00: the one text it could not read
    # is the clock's value, printed alone (learnt at once, before the next digits are typed)
    truth = model_from(
        OVEN.replace("{initial}", "12:00:00").replace("{show}", 'show: "{value}"')
        + 'display: {idle: "{clock}"}\n'
    )
    belief = model_from(
        OVEN.replace("{initial}", "01:00:00")
        .replace("{show}", "label: CLOCK")
        .replace('entry: {format: "h:mm", max_digits: 4}', 'entry: {format: "hh:mm"}')
    )
    episode, reached = run(truth, belief, {"clock": "06:15:00"})
    assert reached and episode.claimed_success
    assert any(r.startswith("clock is shown as '{value}'") for r in episode.repairs)
    assert episode.reasoning_steps == 2  # not one macro action per digit until "6:15" shows


def test_a_time_found_inside_a_longer_time_is_no_template() -> None:
    # a 24-hour clock the panel prints "00:07" (hh:mm) as the digits go in, where the belief
    # prints "CLOCK 0:07" (h:mm): "0:07" inside "00:07" must not become the template
    # "0{value}", but the panel's own style
    day = (
        OVEN.replace('[["01:00:00", "12:59:00", 60]]', '[["00:00:00", "23:59:00", 60]]')
        .replace("{initial}", "00:00:00")
        .replace('entry: {format: "h:mm", max_digits: 4}', 'entry: {format: "hh:mm"}')
    )
    truth = model_from(
        day.replace("{show}", 'show: "{value}"').replace('format: "h:mm"\n', 'format: "hh:mm"\n')
        + 'display: {idle: "{clock}"}\n'
    )
    belief = model_from(day.replace("{show}", "label: CLOCK"))
    episode, reached = run(truth, belief, {"clock": "07:45:00"})
    assert reached and episode.claimed_success
    assert not any("'0{value}'" in r for r in episode.repairs)
    assert any(r.startswith("clock is shown as '{value}' (hh:mm)") for r in episode.repairs)


LAMP = """
controls: [{id: power, label: POWER}, {id: glow, label: NIGHT GLOW}]
variables:
  power: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "READY"}}
  glow: {type: discrete, values: ["off", "on"]{glow_show}}
actions:
  press_power: {control: power}
  press_glow: {control: glow}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  glow:
    - {actions: [press_glow], variable: glow, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], display: "", hide: true}
display: {idle: "{power}"}
"""


def test_an_on_off_setting_learns_the_one_word_its_lamp_lights() -> None:
    # the panel lights GLOW for "on" and prints nothing for "off"; the reader took the
    # setting for one printed as "NIGHT GLOW on"
    truth = model_from(LAMP.replace("{glow_show}", ', show: {"off": "", "on": "GLOW"}'))
    belief = model_from(LAMP.replace("{glow_show}", ", label: NIGHT GLOW"))
    episode, reached = run(truth, belief, {"power": "on", "glow": "on"})
    assert reached and episode.claimed_success
    # learnt from the walk, or (its label lit alone) from the press that switched it
    assert {"glow 'on' is shown as 'GLOW'", "glow is shown 'on' as 'GLOW'"} & set(episode.repairs)
