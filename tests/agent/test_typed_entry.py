"""A keypad that shows an entry as it is typed, where the belief (read from a manual that
did not say so) expects the value: the digits on their way ("VOL 2" towards 250 ml) are no
wrong value, and the closed loop must not repair or explore on them."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

DISPENSER = """
controls:
  - {id: vol, label: VOL}
  - {id: k0, kind: key, label: "0"}
  - {id: k2, kind: key, label: "2"}
  - {id: k5, kind: key, label: "5"}
  - {id: go, label: POUR}
variables:
  volume: {type: numeric, unit: ml, ranges: [[100, 900, 10]], initial: 300, label: VOL,
           entry: {format: number, max_digits: 3, SHOWS}}
  pouring: {type: discrete, values: ["off", "on"], show: {"off": "", "on": "POURING"}}
actions:
  press_vol: {control: vol}
  press_0: {control: k0, digit: 0}
  press_2: {control: k2, digit: 2}
  press_5: {control: k5, digit: 5}
  press_go: {control: go}
features:
  set_volume:
    - {actions: [press_vol]}
    - actions: [press_0, press_2, press_5]
      variable: volume
      effect: {press_0: digit, press_2: digit, press_5: digit}
  pour: [{actions: [press_go], variable: pouring, effect: toggle}]
display: {idle: "VOL {volume}", indicators: [pouring]}
"""


def dispenser(shows: str) -> str:
    return DISPENSER.replace("SHOWS", f"shows: {shows}")


def test_digits_shown_as_typed_are_no_wrong_value() -> None:
    episode, reached = run(
        model_from(dispenser("typed")),
        model_from(dispenser("value")),
        {"volume": "250 ml", "pouring": "on"},
        "display",
    )
    assert reached and episode.claimed_success, episode.failure
    assert not episode.repairs, episode.repairs  # nothing was wrong with the belief
