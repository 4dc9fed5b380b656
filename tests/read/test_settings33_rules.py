"""Rules of the settings33 session, each on a small manual of our own words: keys named after
all but one mode of a list led by "modes" are one setting of those modes, each key switching to
its own and back to the mode no key names (``roles_mode_keys``)."""

from __future__ import annotations

from apbot.model.variables import DiscreteVariable
from apbot.read import read_manual

# a dehumidifier: a TURBO and a QUIET key beside the list of its modes
DRYER = """
Sicca D-12 dehumidifier

1 THE KEYS

  (1) POWER ..... on / standby
  (2) TURBO ..... fast drying; press again to leave it
  (3) QUIET ..... night drying on / off

2 OPERATING MODES: STANDARD, TURBO, QUIET

STANDARD dries at the humidity you set. TURBO runs the fan at full speed. QUIET keeps the
fan slow for the bedroom. The unit leaves the factory in STANDARD.
"""

DRYER_ACTIONS = ["press_power", "press_turbo", "press_quiet"]


def _mode_steps(model: object, action: str) -> list[object]:
    return [
        s
        for f in model.features.values()  # type: ignore[attr-defined]
        for s in f
        if s.actions == [action] and s.variable == "mode"
    ]


def test_keys_named_after_listed_modes_switch_one_mode_setting() -> None:
    model = read_manual(DRYER, DRYER_ACTIONS).model
    mode = model.variables["mode"]
    assert isinstance(mode, DiscreteVariable)
    assert list(mode.values) == ["standard", "turbo", "quiet"]
    assert mode.initial == "standard"
    # no switch of its own per key: "turbo on" and "quiet on" together is no state it has
    assert "turbo" not in model.variables and "quiet" not in model.variables
    (turbo,) = _mode_steps(model, "press_turbo")
    assert turbo.effect.when == {"mode": "turbo"}  # type: ignore[attr-defined]
    assert turbo.effect.then.to == "standard"  # type: ignore[attr-defined]
    assert turbo.effect.otherwise.to == "turbo"  # type: ignore[attr-defined]
    assert len(_mode_steps(model, "press_quiet")) == 1


# every mode of the list has a key: a pad of go-to keys (another rule), not this one
PADS = DRYER.replace("STANDARD, TURBO, QUIET", "TURBO, QUIET")


def test_a_list_without_a_mode_of_no_key_is_left_to_other_rules() -> None:
    model = read_manual(PADS, DRYER_ACTIONS).model
    mode = model.variables.get("mode")
    assert not (isinstance(mode, DiscreteVariable) and "standard" in mode.values)


# the list names two modes no key selects: which one the keys return to is not said
TWO_FREE = DRYER.replace("STANDARD, TURBO, QUIET", "STANDARD, DRY, TURBO, QUIET")


def test_a_list_with_two_modes_of_no_key_makes_no_setting() -> None:
    model = read_manual(TWO_FREE, DRYER_ACTIONS).model
    assert not _mode_steps(model, "press_turbo")


# a console whose spec table lists its workouts: the keys only go to theirs (no "again")
CONSOLE = """
Remo R-3 rowing console

1 SPECIFICATIONS

  Item      | R-3                  | R-3 Plus
  ----------+----------------------+-----------------------------
  Workouts  | FREE ROW, TIME, DIST | FREE ROW, TIME, DIST, RACE
  Weight    | 28 kg                | 30 kg

2 THE KEYS

  (1) TIME — a workout against the clock
  (2) DIST — a workout over a set distance
  (3) START — starts the workout
"""


def test_a_table_row_of_workouts_gives_keys_that_go_to_their_own() -> None:
    model = read_manual(CONSOLE, ["press_time", "press_dist", "press_start"]).model
    workout = model.variables["workout"]
    assert isinstance(workout, DiscreteVariable)
    assert list(workout.values) == ["free row", "time", "dist"]
    (dist,) = [s for f in model.features.values() for s in f if s.actions == ["press_dist"]]
    assert dist.variable == "workout"
    assert dist.effect.to == "dist"  # type: ignore[union-attr]
