"""Holding a stepping key (▲ / ▼, + / −, a minutes key) is a bigger step of the same setting,
never a guessed on/off switch of its own; each case on a small manual of our own."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.plan.plan import plan
from apbot.read import read_manual
from apbot.sim.simulator import Simulator

# a rowing machine: ▲ / ▼ set the target strokes, holding them moves several at once
ROWER = """
## Panel
- **MODE** — Each press: FREE → TARGET → RACE → FREE.
- **▲** / **▼** — Raise or lower the target shown (20 to 200 strokes, 1 stroke per press).
- **GO** — Starts the session.

## Setting a target
1. Press ▲ or ▼ to change the target by one stroke.
2. Holding ▲ or ▼ for 2 seconds moves the target five steps at once.
"""

# a grill timer: + / − move the time by 1 minute; held, by 15 minutes
GRILL = """
## Keys
- **TIME** — Shows the grilling time (0:05 to 3:00) so that + and − change it.
- **+** / **−** — Change the time by 1 minute per press.
- **START** — Starts grilling.

## Setting the time
1. Press TIME. The time blinks.
2. Press + or − to change the time by 1 minute. Hold + or − for 2 seconds to change it
   by 15 minutes at a time.
"""

# a fan heater: + / − change the level; the manual says nothing of holding them
HEATER = """
## Keys
- **POWER** — Switches the heater on or off.
- **+** / **−** — Raise or lower the heat level (1 to 9).
"""


def _errors(model: object) -> list[object]:
    return [p for p in check_model(model) if p.severity == "error"]  # type: ignore[arg-type]


def test_a_held_arrow_skips_the_count_of_steps_the_manual_gives() -> None:
    actions = ["press_mode", "press_up", "press_down", "hold_up", "hold_down", "press_go"]
    model = read_manual(ROWER, actions).model
    assert not _errors(model)
    assert not [v for v in model.variables if v.endswith("_hold")]
    steps = [s for f in model.features.values() for s in f if "hold_up" in s.actions]
    assert steps and all("press_up" in s.actions for s in steps)
    effects = {str(s.effect.get("hold_up")) for s in steps}  # type: ignore[union-attr]
    assert any("5" in e for e in effects)


def test_a_held_plus_adds_the_time_the_manual_gives_and_the_planner_may_use_it() -> None:
    actions = ["press_time", "press_plus", "press_minus", "hold_plus", "hold_minus", "press_start"]
    model = read_manual(GRILL, actions).model
    assert not _errors(model)
    assert not [v for v in model.variables if v.endswith("_hold")]
    time = next(v for v in model.variables if "time" in v)
    sim = Simulator(model)
    start = sim.assignment()[time]
    target = {time: "01:05:00" if start != "01:05:00" else "00:50:00"}
    actions_planned = [a.name for a in plan(model, None, target).actions]
    assert "hold_plus" in actions_planned or "hold_minus" in actions_planned


def test_a_hold_the_manual_never_mentions_repeats_the_press() -> None:
    actions = ["press_power", "press_plus", "press_minus", "hold_plus", "hold_minus"]
    model = read_manual(HEATER, actions).model
    assert not _errors(model)
    assert not [v for v in model.variables if v.endswith("_hold")]
    steps = [s for f in model.features.values() for s in f if "hold_plus" in s.actions]
    assert steps
    assert all(s.effect["hold_plus"] == s.effect["press_plus"] for s in steps)  # type: ignore[index]


# a bathroom scale: + / − set the user's height; holding + switches the unit, holding − clears
SCALE = """
## Keys
- **SET** — Switches the scale on or off.
- **+** / **−** — Raise or lower the height shown (100 to 220 cm, 1 cm per press).

## Units and memory
Hold + for 3 seconds to show inches instead. Hold − for 5 seconds to clear the stored users.
"""

# a desk lamp: holding ▼ puts the display out, it is no faster brightness step
LAMP = """
## Keys
- **POWER** — Switches the lamp on or off.
- **▲** / **▼** — Brighter or dimmer (levels 1 to 7).

Hold ▼ to turn the display off; any key lights it again.
"""


def _held_in_step(manual: str, actions: list[str], press: str, hold: str) -> bool:
    model = read_manual(manual, actions).model
    steps = [s for f in model.features.values() for s in f if press in s.actions]
    assert steps
    return any(hold in s.actions for s in steps)


def test_a_hold_the_manual_gives_another_job_is_not_a_faster_step() -> None:
    scale = ["press_set", "press_plus", "press_minus", "hold_plus", "hold_minus"]
    assert not _held_in_step(SCALE, scale, "press_plus", "hold_plus")
    assert not _held_in_step(SCALE, scale, "press_minus", "hold_minus")
    lamp = ["press_power", "press_up", "press_down", "hold_up", "hold_down"]
    assert not _held_in_step(LAMP, lamp, "press_down", "hold_down")


# a bread oven: holding + / − runs the clock faster; the 2 hours belong to the START key
OVEN = """
## Keys
- **CLOCK** — Shows the clock so that + and − set it.
- **+** / **−** — Change the value shown by one minute per press.
- **START** — Starts the oven.

Hold + or − to set the clock faster, and press START to add a delay of 2 hours.
"""


def test_a_size_said_of_another_key_in_the_same_sentence_is_not_the_holds() -> None:
    actions = ["press_clock", "press_plus", "press_minus", "hold_plus", "hold_minus", "press_start"]
    model = read_manual(OVEN, actions).model
    steps = [s for f in model.features.values() for s in f if "hold_plus" in s.actions]
    assert steps
    for s in steps:
        assert s.effect["hold_plus"] == s.effect["press_plus"]  # type: ignore[index]
