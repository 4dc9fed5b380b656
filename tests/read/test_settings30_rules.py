"""Rules of the settings30 session, each on a small manual of our own words: a key whose step is
followed by turning a named dial gets a setting of its own set by that dial
(``roles_lent_dial``)."""

from __future__ import annotations

from apbot.read import read_manual

# a mixer whose GAIN knob also sets the echo and the reverb after their keys
MIXER = """
Tavo M-4 desk mixer

  ⏻ ........ on / standby
  GAIN ..... knob: the output level
  ECHO ..... selects the echo amount for the knob
  REVERB ... selects the reverb amount for the knob

OUTPUT LEVEL

Turn the GAIN knob to set the output level from 0 to 30 dB.

EFFECTS (ECHO / REVERB)

 1. Press ECHO. The screen shows the echo amount, e.g. ECHO 2.
 2. Turn the GAIN knob: one click changes it by 1, from 0 to 9.
 3. Press REVERB to adjust the reverb in the same way.
 4. After 5 seconds the knob goes back to the output level.
"""

MIXER_ACTIONS = ["press_power", "turn_gain_cw", "turn_gain_ccw", "press_echo", "press_reverb"]


def test_a_key_followed_by_a_turn_of_a_named_dial_sets_its_own_amount() -> None:
    model = read_manual(MIXER, MIXER_ACTIONS).model
    echo = next(f for f in model.features.values() if f[0].actions == ["press_echo"])
    assert len(echo) == 2 and echo[1].variable is not None
    assert set(echo[1].actions) == {"turn_gain_cw", "turn_gain_ccw"}
    var = model.variables[echo[1].variable]
    assert [list(r)[:2] for r in var.ranges] == [[0, 9]]  # type: ignore[union-attr]
    # the dial keeps its own setting
    assert any(
        s.variable and s.variable != echo[1].variable and s.actions[0] == "turn_gain_cw"
        for f in model.features.values()
        for s in f
    )


def test_a_key_adjusted_in_the_same_way_takes_the_dial_too() -> None:
    model = read_manual(MIXER, MIXER_ACTIONS).model
    reverb = next(f for f in model.features.values() if f[0].actions == ["press_reverb"])
    assert len(reverb) == 2 and reverb[1].variable is not None
    assert set(reverb[1].actions) == {"turn_gain_cw", "turn_gain_ccw"}


# a glue lamp whose time keys each set the hardening time and switch the lamp on
GLUE_LAMP = """
Brixo GL-3 glue curing lamp

    ┌─────┐ ┌─────┐ ┌─────┐
    │ 15s │ │ 45s │ │ 90s │   (MODE)
    └─────┘ └─────┘ └─────┘

THE KEYS

  Key      Its job
  ──────   ──────────────────────────────────────────────────────────────
  15s      Sets the hardening time to 15 seconds and starts the lamp at once.
  45s      Sets the hardening time to 45 seconds and starts the lamp at once.
  90s      Sets the hardening time to 90 seconds and starts the lamp at once.
  MODE     Chooses UV or WHITE light.
"""

GLUE_ACTIONS = ["press_15s", "press_45s", "press_90s", "press_mode"]


def test_keys_printed_with_amounts_set_one_setting_and_start() -> None:
    model = read_manual(GLUE_LAMP, GLUE_ACTIONS).model
    var = model.variables["hardening_time"]
    assert [list(r) for r in var.ranges] == [[15, 45, 30], [45, 90, 45]]  # type: ignore[union-attr]
    sets = {
        f[0].actions[0]: f[0].set for f in model.features.values() if f[0].actions[0][-1] == "s"
    }
    assert sets == {
        "press_15s": {"hardening_time": 15},
        "press_45s": {"hardening_time": 45},
        "press_90s": {"hardening_time": 90},
    }
    assert "running" in model.variables
