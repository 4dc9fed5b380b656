"""A programme chosen by its own key, which the belief only guesses the appliance starts in:
the agent presses that key rather than claim the guess."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

STERILISER = """
controls: [{id: power, label: POWER}, {id: rinse, label: RINSE}, {id: steam, label: STEAM},
           {id: full, label: FULL}, {id: start, label: START}]
variables:
  power: {type: discrete, values: ["off", "on"], label: POWER, show: {"off": "", "on": HI}}
  running: {type: discrete, values: ["off", "on"], label: RUN, show: {"off": "", "on": RUN}}
  cycle: {type: discrete, values: [rinse, steam, full], label: CYCLE{start},
          show: {rinse: C1, steam: C2, full: C3}}
actions:
  press_power: {control: power}
  press_rinse: {control: rinse}
  press_steam: {control: steam}
  press_full: {control: full}
  press_start: {control: start}
features:
  power:
    - {actions: [press_power], variable: power, effect: toggle}
  rinse:
    - {actions: [press_rinse], variable: cycle, effect: {to: rinse}}
  steam:
    - {actions: [press_steam], variable: cycle, effect: {to: steam}}
  full:
    - {actions: [press_full], variable: cycle, effect: {to: full}}
  start:
    - {actions: [press_start], variable: running, effect: toggle}
guards:
  - {name: power off, when: {power: "off"}, only: [press_power], hide: true}
display: {idle: "{power}"}
"""


def test_a_guessed_start_programme_is_chosen_by_its_key_not_claimed() -> None:
    # the steriliser starts in FULL; the reader, told no start, took the first cycle listed.
    # Power-on shows HI and START shows RUN: nothing but the cycle's own key shows the cycle
    truth = model_from(STERILISER.replace("{start}", ", initial: full"))
    belief = model_from(STERILISER.replace("{start}", ""))
    episode, reached = run(truth, belief, {"cycle": "rinse", "running": "on"})
    assert reached and episode.claimed_success
    assert any("only a guess of the start" in e.text for e in episode.trace)


def test_a_right_guess_costs_one_press() -> None:
    truth = model_from(STERILISER.replace("{start}", ""))
    belief = model_from(STERILISER.replace("{start}", ""))
    episode, reached = run(truth, belief, {"cycle": "rinse", "running": "on"})
    assert reached and episode.claimed_success
    assert episode.execution_steps == 3  # power, RINSE, start


def test_a_stated_start_is_believed() -> None:
    truth = model_from(STERILISER.replace("{start}", ", initial: rinse"))
    episode, reached = run(truth, truth, {"cycle": "rinse", "running": "on"})
    assert reached and episode.claimed_success
    assert episode.execution_steps == 2  # power, start
