"""Rules of the set29a session, each on a small manual of our own words: a hold that opens the
setting its own section is about, stepped by short presses of the panel's keys
(``held_sections``)."""

from __future__ import annotations

from typing import Any

from apbot.read import read_manual

# a pond pump controller with two keys; each setting has a section of its own
POND_PUMP = """
Brookline PX-2 pond pump controller

1  THE PANEL

  [ MODE ]   [ ADJ ]

  MODE key: settings. ADJ key: settings.

2  PUMP LEVEL

  To set the pump level:
  Hold MODE for 4 seconds until the level blinks. Press MODE briefly to step up one level:
  1, 2, 3 … 7, 8, then back to 1. After 8 seconds without a key press the level is kept.

3  WATER KIND

  | Shown | Water       | Note          |
  |-------|-------------|---------------|
  | w1    | Fresh       | garden ponds  |
  | w2    | Brackish    | coastal ponds |
  | w3    | Salt (sea)  | marine tanks  |

  Keep ADJ pressed for 3 s until the kind blinks. Each short press of ADJ shows the next
  kind, w3 being followed by w1 again. Leave the keys alone for 8 s to store the kind.

4  PRESSURE LIMIT

  Setting range: 4.0 bar to 6.0 bar, in steps of 0.5 bar.

  Press MODE and ADJ at the same time and hold both for 3 seconds. MODE raises the limit by
  0.5 bar, ADJ lowers it by 0.5 bar. The limit stops at 4.0 bar and at 6.0 bar.
"""

POND_ACTIONS = ["press_mode", "hold_mode", "press_adj", "hold_adj", "hold_both", "wait_8s"]


def _opened_by(model: Any, hold: str) -> tuple[str, dict[str, object]]:
    """The setting the hold's feature steps next, and how each press steps it."""
    for steps in model.features.values():
        if steps[0].actions == [hold] and len(steps) == 2 and steps[1].variable:
            return steps[1].variable, dict(steps[1].effect)
    raise AssertionError(f"{hold} opens no setting")


def test_a_held_key_opens_the_run_its_section_prints() -> None:
    model = read_manual(POND_PUMP, POND_ACTIONS).model
    var, effect = _opened_by(model, "hold_mode")
    assert var == "pump_level"
    spec = model.variables[var].model_dump()
    assert [list(r) for r in spec["ranges"]] == [[1, 8, 1]]
    assert spec["wrap"] is True
    assert effect == {"press_mode": "next"}


def test_a_held_key_opens_the_coded_list_of_its_section() -> None:
    model = read_manual(POND_PUMP, POND_ACTIONS).model
    var, effect = _opened_by(model, "hold_adj")
    spec = model.variables[var].model_dump()
    assert spec["values"] == ["fresh", "brackish", "salt"]
    assert spec["show"] == {"fresh": "w1", "brackish": "w2", "salt": "w3"}
    assert effect == {"press_adj": "next"}


def test_both_keys_held_together_open_the_stated_range() -> None:
    model = read_manual(POND_PUMP, POND_ACTIONS).model
    var, effect = _opened_by(model, "hold_both")
    spec = model.variables[var].model_dump()
    assert [list(r) for r in spec["ranges"]] == [[4, 6, 0.5]]
    assert spec["unit"] == "bar"
    assert spec["wrap"] is False
    assert effect == {"press_mode": "next", "press_adj": "prev"}


def test_the_pause_that_stores_it_ends_the_setting() -> None:
    model = read_manual(POND_PUMP, POND_ACTIONS).model
    for steps in model.features.values():
        if steps[0].actions in (["hold_mode"], ["hold_adj"]):
            assert all(s.timeout == 8 for s in steps)
