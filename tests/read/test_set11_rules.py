"""Rules of the set11 session, each on a small manual of our own words: clock figures of a
setting told in whole minutes are minutes (``values_labels.whole_minutes_said``), and the stops
an ellipsis leaves out of a printed row (``list_ellipsis.fill_ellipses``)."""

from __future__ import annotations

from apbot.read import read_manual
from apbot.read.list_ellipsis import fill_ellipses
from apbot.read.values_labels import whole_minutes_said

# a foot spa whose BATH key steps a bath time shown as a clock figure
SPA = """
AquaRelax FS-2 foot spa

  Keys: ⏻  BATH  START

  BATH   Bath time.

BATH TIME

 A bath lasts 2 to 8 minutes. Each press of BATH adds one minute; after 8:00 it goes
 back to 2:00.

    2:00 → 3:00 → 4:00 ... → 7:00 → 8:00 → 2:00
"""


def test_a_clock_row_of_a_setting_told_in_minutes_is_minutes_and_seconds() -> None:
    model = read_manual(SPA, ["press_power", "press_bath", "press_start"]).model
    bath = model.variables["bath"]
    assert bath.format == "mm:ss"
    assert [tuple(r) for r in bath.ranges] == [("00:02:00", "00:08:00", 60)]


def test_whole_minutes_need_minute_words_and_no_hours() -> None:
    assert whole_minutes_said(["2:00", "8:00"], ["A bath lasts 2 to 8 minutes."])
    assert whole_minutes_said(["2:00", "3:00"], ["Each press adds one minute."])
    assert not whole_minutes_said(["2:00", "8:00"], ["Each press adds one hour."])
    assert not whole_minutes_said(["2:30", "8:00"], ["A bath lasts 2 to 8 minutes."])
    assert not whole_minutes_said(["2:00", "8:00"], ["Delay the start by 2 to 8 hours."])


def test_an_ellipsis_in_a_row_stands_for_the_stops_on_the_step_before_it() -> None:
    assert fill_ellipses([10, 20, 30, 90], "10 → 20 → 30 … 90", float) == [
        10, 20, 30, 40, 50, 60, 70, 80, 90,
    ]  # fmt: skip
    # no ellipsis, no stops made up: a jump stays a jump
    assert fill_ellipses([10, 20, 30, 90], "10 → 20 → 30 → 90", float) == [10, 20, 30, 90]


# a quilting machine: a switch printed I / O, motif numbers typed and ended with OK, a turn
# key stepping angles the display marks with an r, a flip key with its own lamp symbol
QUILTER = """
Stitchly Q-90 quilting machine

3  THE PANEL

  (A) Display - motif number (m followed by the number) or the angle.
  (B) Flip lamp ⇆ (lit when the motif is flipped).
  Number keys 0-9 and OK - motif number.
  TURN - turn the motif. FLIP - flip the motif.

 Set the main switch I / O on the back to I. The display shows m1 (motif 1).

4  CHOOSING A MOTIF BY NUMBER

 Every motif has a number from 1 to 120.

 1. Type the number: 4 shows m4, then 4 2 shows m42.
 2. Press OK to close the entry.

5  TURNING AND FLIPPING

 TURN turns the motif by 90° per press:

     r0° ─► r90° ─► r180° ─► r270° ─► r0° ...

 FLIP flips the motif. Each press switches the flip on or off.

6  SPEED

 Press SPEED to change the speed:

     300 (start setting) ─► 500 ─► 700 ─► 300 ...
"""

QUILTER_ACTIONS = [
    "switch_main", *[f"press_{d}" for d in range(10)], "press_ok", "press_turn",
    "press_flip", "press_speed",
]  # fmt: skip


def test_a_main_switch_printed_i_o_is_the_power_switch() -> None:
    model = read_manual(QUILTER, QUILTER_ACTIONS).model
    assert model.controls[0].label == "I / O"
    assert model.variables["power"].values == ["off", "on"]


def test_the_number_keys_legend_names_the_number_they_type_and_its_display_letter() -> None:
    model = read_manual(QUILTER, QUILTER_ACTIONS).model
    motif = model.variables["motif"]
    assert [tuple(r) for r in motif.ranges] == [(1, 120, 1)]
    assert motif.show == "m{value}"
    assert "ok" not in model.variables


def test_angles_marked_with_a_letter_are_numbers_and_the_next_key_keeps_its_lamp() -> None:
    model = read_manual(QUILTER, QUILTER_ACTIONS).model
    turn = model.variables["turn"]
    assert turn.show == "r{value}" and turn.unit == "°"
    assert [tuple(r) for r in turn.ranges] == [(0, 270, 90)]
    assert model.variables["flip"].values == ["off", "on"]  # not TURN's angles
    assert model.variables["flip"].show == {"off": "", "on": "⇆"}


def test_a_value_marked_start_setting_is_where_the_setting_starts() -> None:
    model = read_manual(QUILTER, QUILTER_ACTIONS).model
    assert model.variables["speed"].initial == 300


# a sander with a ⏻ that starts the work and no START key
SANDER = """
Grindo S2 palm sander

  (1) ⏻ key   (2) GRIT key

 Hold the sander on the wood, then press ⏻. The sanding symbol ≋ lights and the pad starts.
 To stop, press ⏻ again.

 Press GRIT to choose the next grit. The order is:

     FINE ─► MEDIUM ─► COARSE ─► FINE ...

 The DUST lamp is lit when the dust bag is on (factory setting).
"""


def test_a_power_key_that_starts_the_work_is_the_start_stop() -> None:
    model = read_manual(SANDER, ["press_power", "press_grit"]).model
    assert "power" not in model.variables
    running = next(v for v in model.variables.values() if v.label == "RUN")
    assert running.show == {"off": "", "on": "≋"}
    assert model.variables["grit"].values == ["fine", "medium", "coarse"]  # after "The order is:"


def test_a_three_state_legend_is_no_toggle() -> None:
    text = """
Beamo lantern

  LAMP  Lamp off / on / blinking

 Press LAMP to step through:

     OFF ─► ON (steady, the display shows LAMP) ─► BLINK (warning blink, the display
     shows BLINK) ─► OFF
"""
    model = read_manual(text, ["press_lamp"]).model
    lamp = model.variables["lamp"]
    assert lamp.values == ["off", "on", "blink"]
    assert lamp.show == {"off": "", "on": "LAMP", "blink": "BLINK"}


# a pump with presets whose chart gives each one a pressure range, step and factory value
PUMP = """
Pumpo P3 ball pump

  PRESET  Next preset
  −  Lower goal.
  +  Higher goal.

PRESETS

  Press PRESET: SOCCER ─► HANDBALL ─► VOLLEY ─► SOCCER ...

  Preset     Range            Step      Factory
  ────────   ──────────────   ───────   ───────
  SOCCER     8 - 16 psi       1 psi     9 psi
  HANDBALL   4 - 7 psi        0.5 psi   5 psi
  VOLLEY     4 - 5 psi        0.5 psi   4.5 psi

SETTING THE GOAL PRESSURE

  Press + or − to change it.
"""


def test_a_bare_range_column_in_psi_is_the_lone_amount_per_preset() -> None:
    model = read_manual(PUMP, ["press_preset", "press_minus", "press_plus"]).model
    goal = model.variables["goal"]
    assert goal.unit == "psi" and goal.depends_on == "preset"
    assert [tuple(r) for r in goal.cases["handball"].ranges] == [(4, 7, 0.5)]
    assert goal.cases["soccer"].initial == 9


def test_a_dial_of_positions_takes_the_amounts_its_chart_gives() -> None:
    text = """
Heato H1 fan heater

  LEVEL selector - a rotary switch with positions 0 to 4.

   Position   Display   Output
   ────────   ───────   ──────
      0         P0       500 W
      1         P1       750 W
      2         P2      1000 W
      3         P3      1500 W
      4         P4      2000 W
"""
    model = read_manual(text, ["turn_level_cw", "turn_level_ccw"]).model
    level = model.variables["level"]
    assert level.unit == "W" and level.show["1500"] == "P3"


def test_an_hour_key_sets_the_time_its_legend_names_one_hour_a_press() -> None:
    text = """
Brewo C4 coffee maker

  HOUR key - sets the brew time.

 Press HOUR. Each press moves the brew time one hour later; after 23:00 it goes round to 00:00.
"""
    model = read_manual(text, ["press_hour"]).model
    brew = model.variables["brew_time"]
    assert brew.ranges[0][2] == 3600
