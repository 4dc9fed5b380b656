"""A keypad whose digits the belief reads in the wrong way, where no format reads the whole
entry as shown: the digits are replayed one by one. A minute minder that keeps only two
digits (1, 3, 9 shows 39 min) and a timer that ignores a digit taking it past its range
(4, 0, 0 shows 40 min, for it takes at most 240) both say how they read digits; the belief
(which typed h:mm) learns it and types the goal again."""

from __future__ import annotations

from apbot.model.schema import ApplianceModel
from tests.helpers import model_from, run_checked

DIGITS = "".join(f'\n  - {{id: k{d}, kind: key, label: "{d}"}}' for d in range(10))
PRESSES = "".join(f"\n  press_{d}: {{control: k{d}, digit: {d}}}" for d in range(10))
KEYS = ", ".join(f"press_{d}" for d in range(10))

MINDER = f"""
controls:
  - {{id: timer, label: TIMER}}{DIGITS}
variables:
  timer: {{type: time, ranges: [["00:00:00", "HIGH", 60]], initial: "00:00:00", format: min,
          label: TIMER, entry: {{ENTRY}}}}
actions:
  press_timer: {{control: timer}}{PRESSES}
features:
  set_timer:
    - {{actions: [press_timer]}}
    - {{actions: [{KEYS}], variable: timer}}
display: {{idle: "TIMER {{timer}}"}}
"""


def minder(high: str, entry: str) -> ApplianceModel:
    return model_from(MINDER.replace("HIGH", high).replace("ENTRY", entry))


def test_a_two_digit_minute_keypad_is_learnt_from_its_digits() -> None:
    truth = minder("01:39:00", "format: minutes, max_digits: 2, overflow: shift")
    belief = minder("01:39:00", 'format: "h:mm"')
    episode, reached = run_checked(truth, belief, {"timer": "01:39:00"})
    assert reached, [e.text or (e.action, e.display) for e in episode.trace]
    assert any("minutes, 2 digits kept" in r for r in episode.repairs), episode.repairs


def test_a_digit_past_the_range_is_ignored_and_the_minutes_learnt() -> None:
    truth = minder("04:00:00", "format: minutes")
    belief = minder("04:00:00", 'format: "h:mm"')
    episode, reached = run_checked(truth, belief, {"timer": "04:00:00"})
    assert reached, [e.text or (e.action, e.display) for e in episode.trace]
    assert any("read as minutes" in r for r in episode.repairs), episode.repairs
