"""A programme key around a setting that depends on the programme: probing it moves the
setting, and choosing it starts the setting where the appliance says, not the belief."""

from __future__ import annotations

from tests.helpers import model_from
from tests.helpers import run_checked as run

HOB = """
controls: [{id: mode, label: MODE}, {id: level, label: LEVEL}, {id: timer, label: TIMER},
           {id: up, label: UP}, {id: down, label: DOWN}]
variables:
  mode: {type: discrete, values: [normal, boost], label: MODE}
  level:
    type: numeric
    depends_on: mode
    label: LEVEL
    cases:
      normal: {ranges: [[1, 9, 1]]{normal_start}}
      boost: {ranges: [[{boost_low}, 9, 1]]{boost_start}}
  timer: {type: numeric, ranges: [[0, 12, 1]], unit: h, label: TIMER}
actions:
  press_mode: {control: mode}
  press_level: {control: level}
  press_timer: {control: timer}
  press_up: {control: up}
  press_down: {control: down}
features:
  set_mode:
    - {actions: [press_mode], variable: mode, effect: next}
{level_steps}
  set_timer:
    - {actions: [press_timer]}
    - {actions: [press_up, press_down], variable: timer, effect: {press_up: next, press_down: prev}}
display: {idle: "READY"}
"""

ENTRY_LEVEL = """  set_level:
    - {actions: [press_level]}
    - {actions: [press_up, press_down], variable: level, effect: {press_up: next, press_down: prev}}
"""

READ_LEVEL = """  set_level:
    - {actions: [press_level], variable: level, effect: next}
"""


def _hob(level_steps: str, boost_low: int, normal_start: str = "", boost_start: str = "") -> str:
    return (
        HOB.replace("{level_steps}", level_steps)
        .replace("{boost_low}", str(boost_low))
        .replace("{normal_start}", normal_start)
        .replace("{boost_start}", boost_start)
    )


def test_a_lone_programme_key_is_not_probed_as_the_stepping_pair() -> None:
    # LEVEL only brings the level up; UP and DOWN adjust it. MODE is a lone key that cycles
    # the programme: pressed as a probe it would put the hob in BOOST, where the level is
    # fixed at 9 and UP/DOWN show nothing moving
    truth = model_from(_hob(ENTRY_LEVEL, 9, ", initial: 5"))
    # (the reader's single key wraps round, or the belief could not reach 1 to 4)
    belief = model_from(
        _hob(READ_LEVEL, 9, ", initial: 5").replace(
            "    label: LEVEL\n", "    label: LEVEL\n    wrap: true\n"
        )
    )
    episode, reached = run(truth, belief, {"level": 3})
    assert reached and episode.claimed_success
    assert "press_level only brings level up; press_up, press_down adjust it" in episode.repairs


def test_a_programme_starts_its_setting_where_the_display_first_shows_it() -> None:
    # BOOST starts the level at 9, where the belief has it start at 1: re-choosing BOOST
    # looks like the short way down to 2, and brings the level back to 9 every time
    truth = model_from(_hob(ENTRY_LEVEL, 1, boost_start=", initial: 9"))
    belief = model_from(_hob(ENTRY_LEVEL, 1))
    episode, reached = run(truth, belief, {"mode": "boost", "level": 2})
    assert reached and episode.claimed_success
    assert "level starts at 9 in mode boost" in episode.repairs
    assert not any("sets it to" in r for r in episode.repairs)  # not LEVEL's doing
