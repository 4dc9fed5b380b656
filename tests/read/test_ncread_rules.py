"""Rules from the second blind new-category set (benchmarks/data/newcats), each on a small
manual of our own words."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.value_spans import expand_spans

# a waffle iron whose browning dial is listed in the specification table with its numbered
# detents written as one span
WAFFLE = """
SPECIFICATIONS

  Model                WB-10                      WB-20
  ------------------   ------------------------   ------------------------
  Rated power          1200 W                     1400 W
  Browning levels      OFF, KEEP WARM, 1-6, MAX   OFF, KEEP WARM, 1-6, MAX

CONTROLS

The BROWNING dial clicks into each position and stops at both ends.
"""


def test_a_span_of_numbered_positions_in_a_list_is_one_value_per_position() -> None:
    model = read_manual(WAFFLE, ["turn_browning_cw", "turn_browning_ccw"]).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    values = [v.values for v in model.variables.values() if v.type == "discrete"]
    assert ["off", "keep warm", "1", "2", "3", "4", "5", "6", "max"] in values


def test_a_span_is_kept_as_it_is_without_a_named_position_or_when_too_long() -> None:
    assert expand_spans(["1-2", "3-4", "5-6"]) == ["1-2", "3-4", "5-6"]
    assert expand_spans(["off", "0-60"]) == ["off", "0-60"]
    assert expand_spans(["low", "2–4", "high"]) == ["low", "2", "3", "4", "high"]


# an aroma diffuser's key table: a short-press column with each key's cycle, a hold column
# where two keys name each other for the key lock and one key's hold switches something
DIFFUSER = """
KEYS

  Key        Short press                            Press and hold
  --------   ------------------------------------   ----------------------------
  POWER      on / off                               -
  MODE       CALM → FOCUS → SLEEP → CALM ...        with TIMER, 3 s: key lock
  GLOW       lamp colour red → green → blue → red   3 s: glow on / off
  TIMER      off → 1H → 3H → 6H → off               with MODE, 3 s: key lock

The diffuser starts in CALM with the timer off.
"""
DIFFUSER_ACTIONS = [
    "press_power",
    "press_mode",
    "press_glow",
    "hold_glow",
    "press_timer",
    "hold_mode_and_timer",
]


def test_a_key_table_row_is_read_within_its_own_cell_and_for_its_own_key() -> None:
    model = read_manual(DIFFUSER, DIFFUSER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    timer = next(v for n, v in model.variables.items() if n.startswith("timer"))
    assert getattr(timer, "values", None) != ["calm", "focus", "sleep"]  # MODE's row
    assert timer.type == "numeric" and timer.ranges[-1][1] == 6


def test_an_on_off_in_the_hold_column_leaves_the_short_press_its_cycle() -> None:
    model = read_manual(DIFFUSER, DIFFUSER_ACTIONS).model
    pressed = [f for fs in model.features.values() for f in fs if f.actions == ["press_glow"]]
    assert pressed and pressed[0].effect == "next"
    assert model.variables[pressed[0].variable].values == ["red", "green", "blue"]


# a two-zone griddle: the zone key's cycle is one sentence, an on/off about the zones another
GRIDDLE = """
CONTROLS

SIDE   Chooses which half of the griddle heats. Each press moves on by one:
       BOTH (both lamps lit) > LEFT only > RIGHT only > BOTH ...
TIMER  Sets the timer in minutes.

TIPS

With AUTO OFF switched on, the heated sides also switch off when the timer ends.
"""


def test_a_cycle_of_named_values_beats_an_on_off_said_elsewhere() -> None:
    model = read_manual(GRIDDLE, ["press_side", "press_timer_up", "press_timer_down"]).model
    side = model.variables["side"]
    assert side.values == ["both", "left", "right"]


# a milk frother whose START key has a long press of its own
FROTHER = """
USING THE FROTHER

Press START to begin frothing; press it again to stop.
Press FOAM to step through LIGHT → DENSE → HOT MILK.
To turn STAY HOT on or off, press and hold START for 2 seconds. The STAY HOT lamp lights.
"""


def test_holding_start_switches_the_setting_the_manual_names_instead_of_stopping() -> None:
    model = read_manual(FROTHER, ["press_start", "hold_start", "press_foam"]).model
    held = [(n, f) for n, fs in model.features.items() for f in fs if f.actions == ["hold_start"]]
    assert held and held[0][1].effect == "toggle"
    assert held[0][1].variable == "stay_hot"


# a two-ring hot plate: the ring key's choice written with a noun after each name, and a row
# for two keys held together whose on/off is the lock's
HOTPLATE = """
KEYS

  RING          Changes between the LEFT ring and the RIGHT ring. Its lamp shows
                which ring the dial sets.
  TIMER         Sets the timer.
  RING + TIMER  Held together for 3 seconds: key lock on / off (LOCK lamp).
"""


def test_names_with_a_shared_noun_are_the_values_and_a_held_pair_row_no_toggle() -> None:
    model = read_manual(HOTPLATE, ["press_ring", "press_timer", "hold_ring_and_timer"]).model
    pressed = [f for fs in model.features.values() for f in fs if f.actions == ["press_ring"]]
    assert pressed and pressed[0].effect in ("next", "toggle")
    assert model.variables[pressed[0].variable].values == ["left", "right"]


# an embroidery machine: designs chosen by number on the digit keys, closed with ENTER
EMBROIDERY = """
PANEL

  0 - 9     Digit keys: type the design you want (see the design list).
  ENTER     Ends the entry of a design number.
  START     Starts stitching the design.
"""


def test_a_key_that_ends_the_entry_of_a_number_names_the_setting_after_that_number() -> None:
    digits = [f"press_{n}" for n in range(10)]
    model = read_manual(EMBROIDERY, [*digits, "press_enter", "press_start"]).model
    assert "design" in model.variables
    assert "enter" not in model.variables


# a toaster-grill whose keep-warm key says on/off in its own row, the programme list nearby
TOASTER = """
## Controls

| Control | Use |
|---|---|
| MODE dial | Turn to pick a programme. |
| START | Starts; press again to stop. |
| WARM | Keep warm on/off. |

The four programmes are printed around the dial, clockwise: GRILL, BAKE, TOAST, DEFROST.
"""


def test_a_key_whose_own_row_says_on_off_stays_a_switch_beside_a_list() -> None:
    actions = ["turn_mode_cw", "turn_mode_ccw", "press_start", "press_warm"]
    model = read_manual(TOASTER, actions).model
    pressed = [f for fs in model.features.values() for f in fs if f.actions == ["press_warm"]]
    assert pressed and pressed[0].effect == "toggle"


# a hand mixer whose speed key's legend has a second line for holding it
MIXER = """
KEYS

  SPEED       Short press: LOW > MEDIUM > HIGH > LOW ...
              Hold for 2 seconds: turbo boost on/off (TURBO lamp).
  POWER       Switches the mixer on or off.
"""

# a bedside lamp's key table with a column for holding each key
BEDSIDE = """
KEYS

  Key       Short touch                  Touch and hold
  -------   --------------------------   ----------------------
  POWER     on / off                     -
  TONE      warm → neutral → cool        2 s: wake-up sound on / off
"""


def test_the_hold_part_of_a_key_legend_names_the_toggle_the_hold_switches() -> None:
    model = read_manual(MIXER, ["press_speed", "hold_speed", "press_power"]).model
    held = [f for fs in model.features.values() for f in fs if f.actions == ["hold_speed"]]
    assert held and held[0].effect == "toggle" and held[0].variable == "turbo_boost"
    model = read_manual(BEDSIDE, ["press_power", "press_tone", "hold_tone"]).model
    held = [f for fs in model.features.values() for f in fs if f.actions == ["hold_tone"]]
    assert held and held[0].effect == "toggle" and held[0].variable == "wake_up_sound"


# a hot chocolate maker: TEMP opens a typed entry, OK only closes it and, held, locks the keys
CHOCO_MAKER = """
KEY FUNCTIONS

 ①  POWER         Switches the frother on or off; your settings stay as long as it is
                  plugged in.
 ②  TEMP          Opens the temperature entry. Type it with the number keys.
 ③  0 – 9         Number keys for the temperature.
 ④  OK            Confirms an entry. Hold 3 s: key lock on/off.

SETTING THE TEMPERATURE

The milk is heated to any whole degree from 40 °C to 75 °C.

  1. Press TEMP.
  2. Type the temperature, e.g. 6 then 5 for 65 °C.
  3. Press OK to confirm. A value outside 40–75 is refused.
"""
CHOCO_MAKER_ACTIONS = ["press_power", "press_temp", "press_ok", "hold_ok"] + [
    f"press_{d}" for d in range(10)
]


def test_a_key_that_only_confirms_an_entry_is_not_a_setting_the_number_keys_type() -> None:
    model = read_manual(CHOCO_MAKER, CHOCO_MAKER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    typed = [
        step.variable
        for steps in model.features.values()
        for step in steps
        if "press_6" in step.actions and step.variable
    ]
    assert typed and all(model.variables[v].label.upper().startswith("TEMP") for v in typed)
