"""Rules drawn from last session's blind set I5, each on a small manual in our own words: a
cycle with OFF among its names, an aside in brackets inside a bare list, the lock that another
key's own row claims."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.value_lists import bare_list

# a key stepping through OFF and two names, said to switch the thing on and off
WAKE = """TOKI WR-2 wake-up light
Instructions

KEYS
  CALL      wake-up OFF / LIGHT / SOUND
  LAMP      lamp on / off

Wake-up (switching the wake-up on and off)
  Press CALL to choose how you wake up:
      OFF → LIGHT (☀ sun icon) → SOUND (♪ note icon) → OFF …
"""
WAKE_ACTIONS = ["press_call", "press_lamp"]


def test_a_cycle_with_off_among_its_names_is_a_selector_not_a_switch() -> None:
    model = read_manual(WAKE, WAKE_ACTIONS).model
    values = {tuple(v.values or []) for v in model.variables.values()}
    assert ("off", "light", "sound") in values


def test_a_bare_list_skips_bracketed_asides_and_a_trailing_ellipsis() -> None:
    items = bare_list("OFF → LIGHT (  sun icon) → SOUND (  note icon) → OFF …")
    assert items == ["OFF", "LIGHT", "SOUND"]


# two held keys, the lock's own row next to the other key's
PANEL = """KIVA H-3 steam room panel

  ①  ⏻        Switches the panel on and off.
  ②  ▲        Raises the value being set.
  ③  ▼        Lowers the value being set.
  ④  TIME     Touch: session time.  Touch and hold 3 s: start delay.
  ⑤  FAN      Touch: fan on / off.  Touch and hold 3 s: key lock.

Key lock
  Touch and hold FAN for 3 seconds. The display shows Loc.
"""
PANEL_ACTIONS = ["press_power", "press_up", "press_down", "press_time", "hold_time",
                 "press_fan", "hold_fan"]  # fmt: skip


def test_a_hold_is_not_the_lock_when_another_key_s_own_row_says_its_hold_is() -> None:
    model = read_manual(PANEL, PANEL_ACTIONS).model
    (lock,) = [s for s in model.features.values() if s[0].variable == "child_lock"]
    assert lock[0].actions == ["hold_fan"]
    assert model.variables["child_lock"].show == {"off": "", "on": "Loc"}


def test_a_chain_of_values_joined_by_en_dashes_is_one_stepped_list() -> None:
    from apbot.read.values import find_ranges

    (found,) = find_ranges("Each press changes it by 5 ml: 10 – 15 – 20 – 25 – 30 ml")
    assert (found.low, found.high, found.unit, found.step) == (10, 30, "ml", 5)


# a key table with a column for holding; a mode word ending in -UP beside the ▲ key
SHOWER = """RIVA DS-1 shower panel

  Key legend

   No.  Key      Touch                          Touch and hold 3 seconds
   ---  -------  -----------------------------  ------------------------------
   1    FLOW     next flow: LOW → HIGH → LOW    -
   2    OUTLET   next outlet: RAIN → HAND       WARM-UP on / off
   3    ▲        warmer, + 0.5 °C               release / restore the 40 °C stop
   4    ▼        cooler, − 0.5 °C               -

  WARM-UP appears while the warm-up is on.
"""
SHOWER_ACTIONS = ["press_flow", "press_outlet", "hold_outlet", "press_up", "hold_up",
                  "press_down"]  # fmt: skip


def test_a_token_is_not_a_part_of_a_hyphenated_word_and_a_held_cell_s_job_is_no_fast_step() -> None:
    model = read_manual(SHOWER, SHOWER_ACTIONS).model
    assert {c.id: c.label for c in model.controls}["up_control"] == "▲"
    stepping = [s for steps in model.features.values() for s in steps if "press_up" in s.actions]
    assert stepping and all("hold_up" not in s.actions for s in stepping)


# the lock's key says its hold is the lock, and so does another key's row (only to say that
# hold is barred while locked): neither claim rules out the other, the lock stays reachable
PURIFIER = """ORBA P-2 purifier

Controls
  MODE     Press to choose AUTO, SLEEP or TURBO.
  TIMER    Press to set the off timer. Touch and hold TIMER for 3 s to clear the timer
           (not possible while the key lock is on).
  LIGHT    Press to dim the light.

Key lock
  Touch and hold LIGHT for 3 seconds to lock the keys. LOC appears.
"""
PURIFIER_ACTIONS = ["press_mode", "press_timer", "hold_timer", "press_light", "hold_light"]


def test_a_hold_whose_own_rows_say_lock_stays_the_lock_when_another_row_says_so_too() -> None:
    model = read_manual(PURIFIER, PURIFIER_ACTIONS).model
    (lock,) = [s for s in model.features.values() if s[0].variable == "child_lock"]
    assert "hold_light" in lock[0].actions


def test_two_ranges_side_by_side_joined_by_a_spaced_dash_are_no_chain() -> None:
    from apbot.read.values import find_ranges

    found = [(r.low, r.high, r.unit) for r in find_ranges("Rice 1–4 – 30–45 min")]
    assert found == [(1, 4, ""), (30, 45, "min")]


# a quick reference flattened column by column: the lock word sits before TIMER's hold, which
# says nothing of the lock; the lock is SIZE's hold, said after it
FLATTENED = """FROSTA IM-1 ice maker

Controls
  SIZE     Press to choose S, M or L cubes.
  TIMER    Press to set the hours. Press and hold TIMER for 3 seconds to clear the timer.

QUICK REFERENCE
  I want to ... lock / unlock the keys clear the timer Press hold TIMER 3 s hold SIZE 3 s

Key lock
  Press and hold SIZE for 3 seconds: LOCK lights and every key is blocked.
"""
FLATTENED_ACTIONS = ["press_size", "hold_size", "press_timer", "hold_timer"]


def test_a_lock_word_before_a_key_s_hold_in_a_flattened_table_is_not_that_hold_s() -> None:
    model = read_manual(FLATTENED, FLATTENED_ACTIONS).model
    (lock,) = [s for s in model.features.values() if s[0].variable == "child_lock"]
    assert lock[0].actions == ["hold_size"]


# a held key whose hold switches an incubation stage named "lockdown", and no key lock at all
BROODER = """HATCHA B-4 brooder

  KEYS
  ⏻       switches the brooder on and off
  TURN    press: egg turning on / off.  Hold 3 s: lockdown on / off (the last three days,
          turning stops and the humidity rises)
  ▲ / ▼   change the temperature
"""
BROODER_ACTIONS = ["press_power", "press_turn", "hold_turn", "press_up", "press_down"]


def test_a_hold_that_starts_a_lockdown_stage_is_not_the_key_lock() -> None:
    model = read_manual(BROODER, BROODER_ACTIONS).model
    assert "child_lock" not in model.variables
