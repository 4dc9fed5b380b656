"""Lengths in millimetres, and a key table's column kept for holding: each rule on a small
manual of our own words."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.model.values import parse_quantity
from apbot.read import read_manual
from apbot.read.roles_holdcell import lock_or_appliance
from apbot.read.value_steps import find_step
from apbot.read.values import find_ranges

# a hedge trimmer: the blade gap set by a knob, in millimetres
TRIMMER = """
HedgePro HT-3 hedge trimmer

BLADE GAP
The blade gap is set with the GAP knob, from 10 mm to 30 mm in five steps of 5 mm.
Turn clockwise for thicker branches.
"""


def test_a_range_in_millimetres_is_read_with_its_unit_and_step() -> None:
    line = "from 10 mm to 30 mm in five steps of 5 mm"
    (found,) = find_ranges(line)
    assert (found.low, found.high, found.unit) == (10, 30, "mm")
    assert find_step(line) == (5, "mm")  # "five steps" is a count, "of 5 mm" the step


def test_a_knob_in_millimetres_becomes_a_numeric_setting_in_mm() -> None:
    model = read_manual(TRIMMER, ["turn_gap_cw", "turn_gap_ccw"]).model
    gap = model.variables["gap"]
    assert gap.type == "numeric" and gap.unit == "mm"
    assert [list(r) for r in gap.ranges] == [[10, 30, 5]]


def test_lengths_are_quantities_in_millimetres() -> None:
    assert parse_quantity("3 centimetres")[:2] == (30, "length")  # type: ignore[index]
    assert parse_quantity("45 mm")[:2] == (45, "length")  # type: ignore[index]


# a bread slicer whose key table is numbered and keeps a column for holding
SLICER = """
SliceMate BS-2 bread slicer

  No.  Key         Press                         Press and hold
  ---  ----------  ----------------------------  ---------------------------------
  1    ⏻           --                            3 s: switch on / off
  2    THICK       next slice thickness          --
  3    START/STOP  start or stop slicing         3 sec: crumb tray on / off (TRAY)
  4    LOCK        --                            3 s: key lock on / off

THICK cycles THIN → MEDIUM → THICK → THIN.
"""
SLICER_ACTIONS = ["hold_power", "press_thick", "press_start", "hold_start", "hold_lock"]


def _slicer():  # type: ignore[no-untyped-def]
    model = read_manual(SLICER, SLICER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    return model


def test_a_numbered_row_whose_hold_column_switches_on_and_off_is_the_power() -> None:
    model = _slicer()
    power = [f for f in model.features.values() if f[0].variable == "power"]
    assert power and power[0][0].actions == ["hold_power"]


def test_holding_the_start_key_switches_what_its_hold_column_names() -> None:
    model = _slicer()
    tray = model.variables["crumb_tray"]
    assert tray.values == ["off", "on"]
    step = model.features["crumb_tray"][0]
    assert step.actions == ["hold_start"] and step.effect == "toggle"
    assert "cancel" not in model.features


def test_a_hold_switching_the_lock_or_the_appliance_names_no_setting() -> None:
    """One list for every hold: the key lock by any of its names, or the appliance itself."""
    for noun in ("key lock", "childlock", "child safety", "keys", "appliance", "power"):
        assert lock_or_appliance(noun), noun
    for noun in ("crumb tray", "warm mist", "end signal", "clock display", "power saving"):
        assert not lock_or_appliance(noun), noun
    assert lock_or_appliance("main power")


# a panel heater whose hold column switches the clock display and power saving
HEATER = """HEATA panel heater

| Key | Press | Hold 3 s |
|-----|-------|----------|
| MODE | comfort / eco / frost | clock display on / off |
| TIMER | timer 1–24 h | power saving on / off |
| + | up | |
| − | down | |
"""


def test_a_clock_or_power_saving_held_on_and_off_is_a_setting() -> None:
    """A clock is no lock, and "power saving" no power switch: each a setting of its own."""
    actions = ["press_mode", "hold_mode", "press_timer", "hold_timer", "press_plus", "press_minus"]
    model = read_manual(HEATER, actions).model
    assert model.features["clock_display"][0].actions == ["hold_mode"]
    assert model.features["power_saving"][0].actions == ["hold_timer"]


# a juicer whose key legend says each hold's job in a sentence of its own
JUICER = """PressFresh J-4 slow juicer

KEYS

  PULP          short press: pulp level 1 → 2 → 3
  SPIN          hold 3 seconds: froth mode on / off

| Key | What it does |
|-----|--------------|
| SENSOR | Hold for 2 seconds: switches the cup sensor on or off. |

  AUTO OFF      Hold 3 seconds to switch the auto switch-off off or on.
"""


def test_a_hold_named_by_the_thing_its_legend_switches() -> None:
    """The hold's job after the key's name on its line, as a row's first sentence, or said with
    the verb ("switches the cup sensor on or off", "to switch the auto switch-off off or on"):
    the setting is named by that thing, never by the gesture ("sensor_hold")."""
    actions = ["press_pulp", "hold_spin", "hold_sensor", "hold_auto_off"]
    model = read_manual(JUICER, actions).model
    assert model.features["froth"][0].actions == ["hold_spin"]
    assert model.features["cup_sensor"][0].actions == ["hold_sensor"]
    assert model.features["auto_switch_off"][0].actions == ["hold_auto_off"]
    assert not {"spin_hold", "sensor_hold", "auto_off_hold"} & set(model.variables)


# a hair clipper: one key, a job per way of touching, the held job switching a "speed" mode
CLIPPER = """
TrimLine C-5 hair clipper

KEYS
  ⏻          Switch on / off.
  GUARD      Press: next guard length. Hold 2 seconds: turbo speed on / off.

GUARD steps 3 mm → 6 mm → 9 mm → 12 mm → 3 mm.
"""


def test_a_held_job_said_as_on_off_is_a_toggle_though_its_noun_names_an_amount() -> None:
    model = read_manual(CLIPPER, ["press_power", "press_guard", "hold_guard"]).model
    turbo = model.variables["turbo_speed"]
    assert list(turbo.values) == ["off", "on"]  # type: ignore[union-attr]
    assert any(
        s.variable == "turbo_speed" and s.effect == "toggle" and s.actions == ["hold_guard"]
        for steps in model.features.values()
        for s in steps
    )


# a radiator: the touch switches the weekly timer on and off, the hold sets its time
RADIATOR = """
WarmWall R-9 radiator

Touch keys
  (1) ⏻       touch: on / off (standby)
  (2) ▲       warmer
  (3) ▼       cooler
  (4) CLOCK   touch: weekly heating timer on / off
              hold 3 s: set the start of the heating time

The heating time starts between 0:00 and 23:30, in half-hour steps.
"""


def test_a_touch_said_as_on_off_beside_a_hold_is_a_toggle_though_it_names_a_timer() -> None:
    actions = ["press_power", "press_up", "press_down", "press_clock", "hold_clock"]
    model = read_manual(RADIATOR, actions).model
    timer = model.variables["weekly_heating_timer"]
    assert list(timer.values) == ["off", "on"]  # type: ignore[union-attr]
    assert any(
        s.variable == "weekly_heating_timer" and s.actions == ["press_clock"]
        for steps in model.features.values()
        for s in steps
    )
