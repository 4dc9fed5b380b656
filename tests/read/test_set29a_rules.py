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


# an antenna rotator: keys printed as signed amounts, two keys of opposite states, a hold named
# by its section's subject, holds named by their jobs, an abbreviated key glossed in its legend
ROTATOR = """
Aerion AR-4 antenna rotator control box

1. THE FRONT PANEL

   [ −1 ]  [ +1 ]  [ −15 ]  [ +15 ]
   [ LOCK ]  [ FREE ]  [ ILLUM ]

   (1) LOCK – lock the rotator on the bearing shown
   (2) FREE – unlock the rotator, turn the mast by hand
   (3) ILLUM – illumination level

   The box powers up with the mains and starts in FREE.

2. TURNING THE ANTENNA

   With the rotator locked, −1 and +1 turn it one degree, −15 and +15 fifteen degrees.
   The bearing is a compass direction from 0 to 359. It runs on past north: +1 at 359 gives 0.
   In FREE these keys do not change the bearing; the box beeps. Press LOCK first.

3. QUICK SWEEPS

   To sweep EAST, hold +1 and +15 together for a second: the bearing changes by 90° to the
   east (e.g. 300° → 030°).

4. ROTATION SPEED

   The rotation speed can be set while the rotator is locked.
   1. Hold −1 and +1 together for two seconds. The display shows SPD and the speed.
   2. Press +1 to raise the speed, −1 to lower it (1 is the lowest, 5 the highest).
   3. Wait 4 seconds without a key: the display returns to the bearing.

5. PANEL LIGHT

   Each press of ILLUM steps the light: OFF → 1 → 2 → OFF.
"""

ROTATOR_ACTIONS = [
    "press_lock",
    "press_free",
    "press_minus1",
    "press_plus1",
    "press_minus15",
    "press_plus15",
    "hold_sweep_east",
    "hold_speed",
    "press_illum",
    "wait_4s",
]


def test_keys_named_by_signed_amounts_find_their_printing() -> None:
    model = read_manual(ROTATOR, ROTATOR_ACTIONS).model
    labels = {c.label for c in model.controls}
    assert {"−1", "+1", "−15", "+15"} <= labels


def test_a_count_said_as_what_it_is_from_a_to_b_runs_on_past_its_ends() -> None:
    model = read_manual(ROTATOR, ROTATOR_ACTIONS).model
    spec = model.variables["bearing"].model_dump()
    assert [list(r) for r in spec["ranges"]] == [[0, 359, 1]]
    assert spec["wrap"] is True


def test_a_hold_named_by_its_sections_subject_opens_it() -> None:
    model = read_manual(ROTATOR, ROTATOR_ACTIONS).model
    var, effect = _opened_by(model, "hold_speed")
    spec = model.variables[var].model_dump()
    assert [list(r) for r in spec["ranges"]] == [[1, 5, 1]]
    assert effect == {"press_plus1": "next", "press_minus1": "prev"}


def test_a_hold_named_by_its_job_adds_its_examples_change() -> None:
    model = read_manual(ROTATOR, ROTATOR_ACTIONS).model
    steps = [s for f in model.features.values() for s in f if s.actions == ["hold_sweep_east"]]
    assert [s.model_dump(include={"variable", "effect"}) for s in steps] == [
        {"variable": "bearing", "effect": {"hold_sweep_east": {"add": 90}}}
    ]


def test_keys_with_opposite_legend_verbs_choose_the_states_of_one_setting() -> None:
    model = read_manual(ROTATOR, ROTATOR_ACTIONS).model
    spec = model.variables["mode"].model_dump()
    assert spec["values"] == ["free", "lock"]
    chosen = {
        s.actions[0]: s.model_dump()["effect"]
        for f in model.features.values()
        for s in f
        if s.variable == "mode"
    }
    assert chosen == {"press_lock": {"to": "lock"}, "press_free": {"to": "free"}}
    guard = next(g for g in model.guards if g.when == {"mode": "free"})
    assert "press_plus1" not in guard.only and "press_lock" in guard.only


def test_an_abbreviated_key_s_setting_takes_its_legend_noun() -> None:
    model = read_manual(ROTATOR, ROTATOR_ACTIONS).model
    assert "illumination_level" in model.variables
    assert "illum" not in model.variables
