"""A programme's start value of its own setting, guessed by the reader, is learnt from a look."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

STEAMER = """
controls: [{id: menu}, {id: time}, {id: up}, {id: down}]
variables:
  menu: {type: discrete, values: [fish, stew], label: MENU}
  cook_time:
    type: time
    format: "h:mm"
    label: TIME
    depends_on: menu
    cases:
      fish: {ranges: [["00:10:00", "00:40:00", 300]]STARTS_FISH}
      stew: {ranges: [["01:00:00", "03:00:00", 600]]STARTS_STEW}
actions:
  press_menu: {control: menu}
  press_time: {control: time}
  press_up: {control: up}
  press_down: {control: down}
features:
  menu: [{actions: [press_menu], variable: menu, effect: next}]
  cook_time:
    - {actions: [press_time]}
    - {actions: [press_up, press_down], variable: cook_time,
       effect: {press_up: next, press_down: prev}}
display:
  idle: "{menu}"
"""


def test_a_look_that_shows_where_a_programme_starts_its_setting_is_learnt() -> None:
    # the manual gave the stew's range but not where it starts (2:00): the belief guesses its
    # first value, 1:00 — the goal's — and would otherwise choose the stew again and again to
    # bring the time back to a start it never had
    truth = model_from(
        STEAMER.replace("STARTS_FISH", ", initial: '00:20:00'").replace(
            "STARTS_STEW", ", initial: '02:00:00'"
        )
    )
    belief = model_from(STEAMER.replace("STARTS_FISH", "").replace("STARTS_STEW", ""))
    episode, reached = run(truth, belief, {"menu": "stew", "cook_time": "01:00:00"})
    assert reached and episode.claimed_success
    assert "cook_time starts at '02:00:00' in stew" in episode.repairs


COOKER = """
controls: [{id: menu}, {id: time}, {id: up}, {id: down}]
variables:
  menu: {type: discrete, values: [rice, cake], label: MENU}
  cook_time: {type: time, format: "h:mm", label: TIME, ranges: [["00:30:00", "01:20:00", 300]]START}
actions:
  press_menu: {control: menu}
  press_time: {control: time}
  press_up: {control: up}
  press_down: {control: down}
features:
  menu: [{actions: [press_menu], variable: menu, effect: next, reset: [cook_time]}]
  cook_time:
    - {actions: [press_time]}
    - {actions: [press_up, press_down], variable: cook_time,
       effect: {press_up: next, press_down: prev}}
display:
  idle: "{menu}"
"""


def test_a_look_shows_where_a_reset_brings_a_setting_of_no_programme_back() -> None:
    # the menu's choice resets the baking time, to 0:50 on the appliance; the manual gave only
    # the range, so the belief takes its first value (0:30, the goal's): a look at the time
    # shows 0:50, and choosing the menu again must not look like the way back to 0:30
    truth = model_from(COOKER.replace("START", ", initial: '00:50:00'"))
    belief = model_from(COOKER.replace("START", ""))
    episode, reached = run(truth, belief, {"menu": "cake", "cook_time": "00:30:00"})
    assert reached and episode.claimed_success
    assert "cook_time starts at '00:50:00' when reset" in episode.repairs
