"""Key legends with several functions per key, callout-numbered legends, box-drawn charts and
code columns: each rule on a small manual of our own words."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.text import parse_manual

# a foot spa: a one-letter key with two jobs, a callout-numbered legend with a line carried
# under the key, a box-drawn programme chart whose first column is the display code, a row
# of level keys 1 to 4, and a programme change that puts the jets back to a named value
SPA = """
AquaRest Foot Spa FS-2

Fill the spa with warm water before you switch it on. Never move the spa while it is full.

THE KEYPAD

  ①  P          Hold for 3 seconds: switch the spa on or off.
                Press briefly: next programme.
  ②  JETS       Jets: SOFT → STRONG → SOFT.
  ③  Level keys Touch a key to choose the warmth at once: 1 (tepid) to 4 (hot).

PROGRAMMES

  ┌──────┬──────────────┬────────────────────────────┐
  │ Code │ Programme    │ What it does               │
  ├──────┼──────────────┼────────────────────────────┤
  │ C1   │ CALM         │ slow bubbles, gentle       │
  │ VB   │ VIBRATE      │ vibration of the footbed,  │
  │      │              │ no bubbles                 │
  │ RF   │ REFRESH      │ cool water pulses          │
  └──────┴──────────────┴────────────────────────────┘

Press P briefly until the code you want is lit: C1 → VB → RF → C1 ...
After RF the display goes back to C1.
Each time you change the programme, the jets go back to SOFT.
"""
SPA_ACTIONS = [
    "hold_p",
    "press_p",
    "press_jets",
    "press_1",
    "press_2",
    "press_3",
    "press_4",
]


def _spa():  # type: ignore[no-untyped-def]
    model = read_manual(SPA, SPA_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    return model


def test_a_box_drawn_chart_is_a_table_with_its_wrapped_cells_joined() -> None:
    units = parse_manual(SPA).units
    rows = [u.cells for u in units if u.cells and u.header and u.header[0] == "Code"]
    assert rows[1] == ("VB", "VIBRATE", "vibration of the footbed, no bubbles")
    assert [r[0] for r in rows] == ["C1", "VB", "RF"]


def test_a_callout_numbered_legend_has_no_header_and_loses_its_callouts() -> None:
    units = parse_manual(SPA).units
    row = next(u for u in units if u.cells and u.cells[0] == "P")
    assert row.header == ()
    assert row.cells[1].endswith("Press briefly: next programme.")  # the line carried under
    assert next(u for u in units if u.cells and u.cells[0] == "JETS").header == ()


def test_holding_a_key_that_switches_the_appliance_itself_is_the_power() -> None:
    model = _spa()
    power = [f for f in model.features.values() if f[0].variable == "power"]
    assert power and power[0][0].actions == ["hold_p"]
    assert any(g.when == {"power": "off"} for g in model.guards)


def test_the_short_press_of_a_letter_key_steps_the_charted_programmes_shown_by_code() -> None:
    model = _spa()
    prog = model.variables["programme"]
    assert prog.values == ["calm", "vibrate", "refresh"]
    assert prog.show == {"calm": "C1", "vibrate": "VB", "refresh": "RF"}
    step = model.features["set_programme"][0]
    assert step.actions == ["press_p"] and step.effect == "next"


def test_a_programme_change_that_names_a_setting_and_a_value_sets_that_value() -> None:
    step = _spa().features["set_programme"][0]
    assert step.set == {"jets": "soft"} and not step.reset


def test_a_row_of_level_keys_sets_its_amount_directly_not_a_keypad_time() -> None:
    model = _spa()
    steps = [f[0] for f in model.features.values() if f[0].actions[:1] == ["press_1"]]
    assert steps and {a: e.to for a, e in steps[0].effect.items()} == {  # type: ignore[union-attr]
        f"press_{n}": n for n in range(1, 5)
    }
    level = model.variables[steps[0].variable]
    assert level.type == "numeric" and [list(r) for r in level.ranges] == [[1, 4, 1]]
    assert not [v for v in model.variables.values() if v.type == "time"]


# a plant lamp whose only power key is touched and held; it is delivered switched on
LAMP = """
GrowBright GL-1 plant lamp

  Symbol        Name            Function
  ------------  --------------  ---------------------------------------
  ⏻             power key       Touch and hold 2 s: switch the lamp
                                off or on again.
  BRIGHT        bright key      Brightness 1 → 2 → 3 → 1.

The lamp is switched on when it leaves the factory.
"""


def test_a_power_key_that_is_only_held_switches_the_appliance_and_starts_on() -> None:
    model = read_manual(LAMP, ["hold_power", "press_bright"]).model
    power = model.variables["power"]
    assert power.initial == "on"
    assert model.features["power"][0].actions == ["hold_power"]


def test_holding_a_key_that_switches_a_setting_is_not_the_power() -> None:
    text = """
Kettle KT-3

  ①  WARM       Press: keep warm on / off.
                Hold for 2 seconds: switch the sound on or off.
  ②  START      Starts boiling.
"""
    model = read_manual(text, ["press_warm", "hold_warm", "press_start"]).model
    assert "power" not in model.variables


# a pasta maker whose start state is printed as one list, and a smoker-like oven whose list
# gives the values alone
PASTA = """
NoodleMate NM-4

  MODE      Shape: SPAGHETTI → PENNE → LASAGNE → SPAGHETTI.
  SPEED     Speed: 1 → 2 → 3 → 1.

Every time you plug it in, the machine starts with these settings:

      mode SPAGHETTI · speed 2
"""
OVEN = """
Roastline RO-9

  TEMP     Sets the temperature, 100 - 250 °C in steps of 10 °C.
  TIME     Sets the roasting time, 0:10 - 6:00 (hours and minutes), in 10-minute steps.

The first time, the oven shows its factory settings: 180 °C and 1:30.
"""


def test_a_printed_list_of_start_settings_gives_each_named_setting_its_start() -> None:
    model = read_manual(PASTA, ["press_mode", "press_speed"]).model
    assert model.variables["mode"].initial == "spaghetti"
    assert model.variables["speed"].initial == 2


def test_a_start_value_without_its_name_goes_to_the_one_setting_that_holds_it() -> None:
    model = read_manual(OVEN, ["press_temp", "press_time", "press_up", "press_down"]).model
    times = [v for v in model.variables.values() if v.type == "time"]
    assert times and times[0].initial == "01:30:00"


# a porridge maker whose programme sets the consistency per grain, and puts it back
PORRIDGE = """
OatPot OP-1

  PROGRAMME    Grain: OATS → RICE → MILLET → OATS.
  CONSISTENCY  Each press: the next consistency the table gives for the grain.
  DELAY        Delayed start, 1 - 12 hours.

  | Programme | Consistency          |
  |-----------|----------------------|
  | OATS      | SMOOTH, CHUNKY       |
  | RICE      | SMOOTH, CREAMY       |
  | MILLET    | SMOOTH               |

Changing the programme returns the consistency to SMOOTH.
"""


def test_a_reset_to_a_named_value_of_a_per_programme_setting_sets_only_that() -> None:
    actions = ["press_programme", "press_consistency", "press_delay"]
    model = read_manual(PORRIDGE, actions).model
    step = next(f[0] for f in model.features.values() if f[0].actions == ["press_programme"])
    assert step.set == {"consistency": "smooth"}
    assert not step.reset


# a bean roaster whose knob has three jobs, told on lines set in under its name
ROASTER = """
BeanCraft BR-2 coffee roaster

  Control       Use
  ------------  --------------------------------------------------------
  POWER         Switch the roaster on or off.
  TEMP          Select the drum temperature for adjustment.
  ROAST knob    Turn: change the selected setting.
                Press: confirm the setting.
                Press and hold 2 seconds: start or stop roasting.

The display shows ROASTING while the drum turns.
"""


def test_a_knob_held_to_start_or_stop_the_run_toggles_running() -> None:
    actions = ["press_power", "press_temp", "turn_roast_cw", "turn_roast_ccw", "press_roast"]
    model = read_manual(ROASTER, [*actions, "hold_roast"]).model
    steps = [f[0] for f in model.features.values() if f[0].actions == ["hold_roast"]]
    assert steps and steps[0].variable == "running" and steps[0].effect == "toggle"


def test_a_hold_printed_as_on_off_after_its_colon_is_the_power() -> None:
    text = """
Breeze tower fan TF-8

  ①  F          Hold 2 s: ON/OFF.
                Press: next speed, LOW → MID → HIGH → LOW.
  ②  SWING      Swing on / off.
  ③  TIMER      Timer: OFF → 1H → 2H → 4H → OFF.
"""
    model = read_manual(text, ["hold_f", "press_f", "press_swing", "press_timer"]).model
    assert model.features["power"][0].actions == ["hold_f"]


# a food processor: rows counted by letters, a hold column headed with its seconds, and the
# hold's on/off cell followed by the sign the display shows
PROCESSOR = """KEYS

  Item  Key     Short touch                       Touch and hold 3 seconds
  ----  ------  --------------------------------  ---------------------------------
  A     ON      Switch on / off                   -
  B     BLADE   Next blade: CHOP → SLICE → GRATE → CHOP   Pulse mode on / off (PLS)
  C     GO      Start or stop                     -
"""
PROCESSOR_ACTIONS = ["press_on", "press_blade", "hold_blade", "press_go"]


def test_a_hold_column_s_on_off_is_the_hold_s_toggle_not_the_press_s() -> None:
    model = read_manual(PROCESSOR, PROCESSOR_ACTIONS).model
    blade = model.variables["blade"]
    assert blade.values == ["chop", "slice", "grate"]  # type: ignore[attr-defined]
    held = [f for f in model.features.values() if f[0].actions == ["hold_blade"]]
    assert held and held[0][0].variable == "pulse", model.features


# a fan heater's legends: a dial whose positions are written "L1 to L4" (no list of its own)
# in the row above a key's arrow cycle, and a numbered legend where a key's range is followed
# by the next key's list of days
LEGEND_NEIGHBOURS = """
Breeze FH-3 fan heater

Keep the heater 1 m from curtains. Do not cover the grille.

THE PANEL

| Ref | Description |
|-----|-------------|
| ① | LEVEL dial — fan level L1 to L4 (4 click positions). |
| ② | SWING — louvre swing on / off. |
| ③ | MODE — heating OFF → LOW → HIGH → OFF. |

| Item | What it does |
|------|--------------|
| (4) DELAY | Start the heater later: 0 to 9 hours. |
| (5) REPEAT | Repeat the start every 1, 2 or 3 days. |

USE

Turn the LEVEL dial clockwise for a stronger fan; it stops at L1 and at L4.
Press MODE to step through the heating settings.
Press DELAY: each press adds one hour, up to 9 hours.
"""

NEIGHBOUR_ACTIONS = [
    "turn_level_cw",
    "turn_level_ccw",
    "press_swing",
    "press_mode",
    "press_delay",
    "press_repeat",
]


def test_a_legend_row_glossing_another_key_gives_this_one_no_values() -> None:
    model = read_manual(LEGEND_NEIGHBOURS, NEIGHBOUR_ACTIONS).model
    level = next(v for v in model.variables.values() if v.label == "LEVEL")
    assert "off" not in (getattr(level, "values", None) or [])  # MODE's cycle is not the dial's
    assert not [g for g in model.guards if "level" in g.when]  # so no "dial at OFF" power guard
    delay = next(v for v in model.variables.values() if v.label == "DELAY")
    assert delay.type == "numeric" and delay.ranges[-1][1] == 9  # not REPEAT's days 1, 2, 3
