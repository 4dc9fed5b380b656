"""Rules from the new-category development set (benchmarks/data/newcats), each on a small manual
of our own."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.value_lists import find_list

# a yoghurt maker whose chart's rows wrap onto two lines, with a per-row step column and the
# styles printed with spaces between them
CHURN = """
## Keys
- **PROGRAM** — Each press moves on: PLAIN → GREEK → SKYR → back to PLAIN.
- **STYLE** — Each press: MILD → TANGY → SOUR → MILD.
- **TIME +** / **TIME -** — Change the time by 30 minutes.
- **START** — Starts.

Times: 4 to 12 hours.

## Chart

 Program   Use                     Styles        Standard   Time
                                   available     time       step
 -------   ---------------------   -----------   --------   ------
 PLAIN     whole milk, cream       MILD TANGY    8 h        30 min
           or skimmed milk
 GREEK     strained after          MILD TANGY    10 h       30 min
           the cycle
 SKYR      skimmed milk only       TANGY SOUR    12 h       30 min
"""


def test_a_chart_with_wrapped_rows_is_one_table_whose_step_column_gives_no_values() -> None:
    actions = ["press_program", "press_style", "press_time_up", "press_time_down", "press_start"]
    model = read_manual(CHURN, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    style = model.variables["style"]
    assert style.depends_on == "program"
    assert style.cases["plain"].values == ["mild", "tangy"]
    assert style.cases["skyr"].values == ["tangy", "sour"]
    time = model.variables["time"]
    assert time.depends_on is None  # the step column is no list of times


# a bread proofer with a two-digit display: programmes shown as codes, a chart naming them,
# chart rows wrapped onto two lines in the PDF text
PROOFER = """
PROOFMATE 200   USER GUIDE

1  SAFETY
Do not place the proofer near a sink. Unplug it before cleaning.

2  KEYS

  Key        Use
  ---------------------------------------------------------------
  ON/OFF     Switches the proofer on or off.
  PROG       Each press goes on to the next programme, A1 → A2 → … → A5 → A1. The
             display shows the programme number.
  START      Starts proofing; press again to stop.

3  PROGRAMME TABLE

  No.    Programme         Temperature    Suits
  ---------------------------------------------------------------
  A1     WHITE DOUGH       28 °C          sandwich loaves, rolls,
                                          buns
  A2     RYE               30 °C          dark breads
  A3     SOURDOUGH         26 °C          levain, starters and
                                          long rises
  A4     BRIOCHE           24 °C          butter doughs
  A5     MELT              40 °C          chocolate, butter

The proofer starts in A1 each time it is switched on.
"""

PROOFER_ACTIONS = ["press_on_off", "press_prog", "press_start"]


def test_an_ellipsis_between_codes_stands_for_the_codes_it_skips() -> None:
    found = find_list("Each press shows the next one: C1 → C2 → … → C5 → C1. Hold it to exit.")
    assert found == (["C1", "C2", "C3", "C4", "C5"], "arrows")


def test_an_arrow_cycle_ends_at_its_sentence_and_at_a_bracket() -> None:
    found = find_list("Sets the grind: FINE → MEDIUM → COARSE → FINE … (see the chart).")
    assert found == (["FINE", "MEDIUM", "COARSE"], "arrows")
    found = find_list("Moves on (in turn: MILD → HOT → EXTRA HOT → back to MILD).")
    assert found == (["MILD", "HOT", "EXTRA HOT"], "arrows")


def test_codes_a_chart_names_become_the_names_and_the_display_shows_the_codes() -> None:
    model = read_manual(PROOFER, PROOFER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    prog = model.variables["prog"]
    assert prog.values == ["white dough", "rye", "sourdough", "brioche", "melt"]
    assert prog.show == {
        "white dough": "A1",
        "rye": "A2",
        "sourdough": "A3",
        "brioche": "A4",
        "melt": "A5",
    }


# a yoghurt maker whose last mode is called "WARM ONLY"
YOGHURT = """
## Keys

- **MODE** — Changes the mode. Each press moves on (order: PLAIN → GREEK → WARM ONLY → back
  to PLAIN).
- **START** — Starts or stops the cycle.
"""


def test_only_in_capitals_inside_a_name_in_capitals_is_part_of_the_name() -> None:
    model = read_manual(YOGHURT, ["press_mode", "press_start"]).model
    assert model.variables["mode"].values == ["plain", "greek", "warm only"]


# a popcorn maker's legend set with wide spaces; the mode row's cycle trails off ("…"), and the
# heat knob's row follows with the kind of control after its name
POPPER = """
POPCORN STATION PS-3

CONTROLS

  Control       What it does
  -----------   ----------------------------------------------------------------
  MODE          Picks what to make: SALTED → SWEET → KETTLE → SALTED …
  HEAT knob     Sets the kettle temperature. It clicks every 10 °C from 150 °C
                to 200 °C and stops at both ends.
  START         Starts or stops popping.
"""


def test_a_legend_row_led_by_a_name_and_its_kind_of_control_is_a_row_of_its_own() -> None:
    actions = ["press_mode", "turn_heat_cw", "turn_heat_ccw", "press_start"]
    model = read_manual(POPPER, actions).model
    assert model.variables["mode"].values == ["salted", "sweet", "kettle"]
    heat = model.variables["heat"]
    assert heat.type == "numeric" and heat.ranges[0][:2] == (150, 200)


# a step sentence about the time right after the temperature key's line
STEPS = """
## Panel
- **TEMP** — then ▲ / ▼ set the temperature, 40 °C to 90 °C.
- Times are kept in 30-minute steps.
- Each press of ▲ / ▼ changes the temperature by 10 °C.
- **TIME** — then ▲ / ▼ set the time, 1 to 10 hours.
"""


def test_a_step_in_another_unit_is_another_settings_step() -> None:
    actions = ["press_temp", "press_time", "press_up", "press_down"]
    model = read_manual(STEPS, actions).model
    assert model.variables["temp"].ranges == [(40, 90, 10)]


# a legend numbered with circled digits: another key's row lends this key nothing
CIRCLED = """
KEY FUNCTIONS

 ①  ON/OFF        Switches the unit on or off. Settings are kept while it is
                  plugged in.
 ②  LEVEL         Opens level entry. Type the level with the number keys.
 ③  SPEED         Changes the speed: SLOW → FAST → TURBO → SLOW ...
 ④  0 – 9         Number keys for the level.

The level goes from 1 to 20.
"""


def test_a_circled_number_does_not_hide_whose_row_it_is() -> None:
    actions = ["press_power", "press_level", "press_speed", *[f"press_{d}" for d in range(10)]]
    model = read_manual(CIRCLED, actions).model
    assert model.variables["speed"].values == ["slow", "fast", "turbo"]
    level = model.variables["level"]
    assert level.type == "numeric"


# a kiln controller: a keypad, a spec sheet with dot leaders, a cook timer under TIMER
KILN = """
SPECIFICATIONS

  Model ........................ K-1            K-2
  Firing temperature ........... 600 - 1200 °C  600 - 1200 °C
  Hold timer ................... 0:00 - 48:00   0:00 - 48:00
  Weight ....................... 38 kg          52 kg

KEYS

 1  TEMP     Opens the temperature, set in whole degrees Celsius. Type it with the
             number keys.
 2  TIMER    Opens the hold timer. Type hours and minutes with the number keys.
 3  0 – 9    Number keys.
 4  START    Starts firing.

The cook timer counts the cooking time at the top temperature.
"""

KILN_ACTIONS = ["press_temp", "press_timer", "press_start", *[f"press_{d}" for d in range(10)]]


def test_whole_degrees_is_a_step_of_one_degree() -> None:
    model = read_manual(KILN, KILN_ACTIONS).model
    temp = model.variables["temp"]
    assert temp.ranges[0][2] == 1


def test_dot_leaders_are_a_gap_between_a_spec_sheets_columns() -> None:
    model = read_manual(KILN, KILN_ACTIONS).model
    assert model.variables["temp"].ranges[0][:2] == (600, 1200)
    assert model.variables["timer"].ranges[0][:2] == ("00:00:00", "48:00:00")


def test_a_cook_timer_keyed_in_after_timer_is_the_only_time_the_digits_set() -> None:
    model = read_manual(KILN, KILN_ACTIONS).model
    times = [n for n, v in model.variables.items() if v.type == "time"]
    assert times == ["timer"]


# a proving drawer: TEMP and HOURS pick what + and - change; the legend ends with a key the
# larger model has (LAMP), switched on and off
DRAWER = """
CONTROL PANEL

  Key        Name            Function
  ----------------------------------------------------------------------
  TEMP       Temperature     Touch once, then use - and + to set the temperature.
  HOURS      Proving time    Touch once, then use - and + to set the hours.
  -   +      Minus / plus    Change the value chosen with TEMP or HOURS.
  LAMP       Lamp            Large model only. Switches the lamp on and off.

SETTING THE TEMPERATURE
  1. Touch TEMP. The display shows the temperature, e.g. 30°C.
  2. Touch + to raise or – to lower the temperature by 5 °C with each touch.
  3. The temperature goes from 25 °C to 45 °C.

SETTING THE HOURS
  1. Touch HOURS. The hours are counted in whole hours.
"""

DRAWER_ACTIONS = ["press_temp", "press_hours", "press_minus", "press_plus"]


def test_each_touch_of_the_pair_makes_the_key_open_the_setting_for_the_pair() -> None:
    model = read_manual(DRAWER, DRAWER_ACTIONS).model
    steps = next(f for f in model.features.values() if f[0].actions == ["press_temp"])
    assert len(steps) == 2 and set(steps[1].actions) == {"press_plus", "press_minus"}


def test_a_key_tables_row_for_a_key_not_on_the_panel_lends_no_toggle() -> None:
    model = read_manual(DRAWER, DRAWER_ACTIONS).model
    steps = next(f for f in model.features.values() if f[0].actions == ["press_hours"])
    assert len(steps) == 2 and set(steps[1].actions) == {"press_plus", "press_minus"}


def test_each_press_of_keys_named_together_stays_each_keys_own() -> None:
    manual = """
## Programmes
| Programme | Soak | Rinse | Dry |
|---|---|---|---|
| Daily | 0 – 10 | 1 – 3 | 0 – 5 |
| Heavy | 10 – 30 | 2 – 4 | 5 – 9 |

## Changing the settings
Press **SOAK**, **RINSE** or **DRY** and watch the display: every press gives the next value
the programme allows. Press **PROGRAMME** to choose the programme.
"""
    actions = ["press_programme", "press_soak", "press_rinse", "press_dry", "press_start"]
    model = read_manual(manual, actions).model
    steps = next(f for f in model.features.values() if f[0].actions == ["press_rinse"])
    assert steps[0].effect == "next" and len(steps) == 1


def test_a_wait_action_is_no_key_but_time_passing() -> None:
    manual = """
## Keys
- **MODE** — Each press: EASY → DEEP → EASY.
- **START** — Starts or stops.
After 5 seconds without a key press the display goes back to the time.
"""
    model = read_manual(manual, ["press_mode", "press_start", "wait_5s", "wait_2_min"]).model
    assert model.actions["wait_5s"].skill == "wait" and model.actions["wait_5s"].seconds == 5
    assert model.actions["wait_2_min"].seconds == 120
    assert not any("wait" in name for name in model.variables)
    assert not any(
        a.startswith("wait") for steps in model.features.values() for s in steps for a in s.actions
    )


# a towel rail: PRESET switches the warm-by time on and off, ▲ / ▼ then move that time
RAIL = """
KEYS

  POWER       Switches the rail on or off.
  PRESET      Switches the warm-by time on or off.
  ▲ ▼         Change the value being set.

WARM-BY TIME
  1. Press PRESET. The display shows the warm-by time (07:00 the first time).
  2. Press ▲ or ▼ to change the warm-by time by 15 minutes per press. After 23:45 comes 00:00.
  3. To switch it off, press PRESET again.
"""


def test_a_key_switching_a_time_on_also_opens_that_time_for_the_pair() -> None:
    model = read_manual(RAIL, ["press_power", "press_preset", "press_up", "press_down"]).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    steps = next(f for f in model.features.values() if f[0].actions == ["press_preset"])
    assert steps[0].effect == "toggle" and len(steps) == 2
    time = model.variables[steps[1].variable]
    assert time.type == "time" and time.ranges == [("00:00:00", "23:45:00", 900)]


def test_a_start_stop_key_only_ever_held_starts_and_stops_and_is_no_lock() -> None:
    manual = """
## Keys
- **LOCK** — Hold 3 s: the key lock goes on or off. While locked, START/STOP does nothing.
- **START/STOP** — Press and hold for 2 seconds to start pumping; hold again to stop.
- **SPEED** — Each press: LOW → HIGH → LOW.
"""
    model = read_manual(manual, ["hold_lock", "hold_start", "press_speed"]).model
    steps = next(f for f in model.features.values() if f[0].actions == ["hold_start"])
    assert steps[0].effect == "toggle" and steps[0].variable == "running"


def test_a_lock_sentence_naming_start_stop_does_not_make_its_hold_the_lock() -> None:
    manual = """
## Keys
- **OK** — Confirms an entry. Hold 3 s: key lock on/off.
- **START/STOP** — Press and hold for 2 seconds to start; hold again to stop.

## Key lock
Press and hold OK for 3 seconds. LOCK appears and all keys are disabled, including
START/STOP, so that a running cycle cannot be stopped by mistake. To release the lock, press
and hold OK for 3 seconds again.
"""
    model = read_manual(manual, ["press_ok", "hold_ok", "hold_start"]).model
    lock = next(f for f in model.features.values() if f[0].variable == "child_lock")
    assert lock[0].actions == ["hold_ok"]


def test_a_hold_of_start_is_still_the_lock_where_no_other_key_is() -> None:
    manual = """
## Keys
- **START** — Starts the kettle. Hold START for 3 s to lock the keys; hold again to unlock.
- **TEMP** — Each press: 70 → 80 → 90 → 100 °C.
"""
    model = read_manual(manual, ["press_start", "hold_start", "press_temp"]).model
    lock = next(f for f in model.features.values() if f[0].variable == "child_lock")
    assert lock[0].actions == ["hold_start"]


def test_an_appliance_delivered_switched_on_starts_on() -> None:
    manual = """
## Keys
- **ON/OFF** — Switches the pump on and off.
- **MODE** — Each press: AUTO → BOOST → AUTO.

When the pump leaves the factory it is in AUTO and switched on.
"""
    model = read_manual(manual, ["press_on_off", "press_mode"]).model
    assert model.variables["power"].initial == "on"


RAIL_DISPLAY = (
    RAIL
    + """
DISPLAY

  WARM 07:00      Warm-by time switched on, warm towels at 07:00
  WARM --:--      No warm-by time
"""
)


def test_the_display_legend_shows_the_switched_time_and_its_first_value() -> None:
    model = read_manual(RAIL_DISPLAY, ["press_power", "press_preset", "press_up", "press_down"])
    steps = next(f for f in model.model.features.values() if f[0].actions == ["press_preset"])
    toggle = model.model.variables[steps[0].variable]
    assert toggle.show == {"off": "WARM --:--", "on": "WARM {" + steps[1].variable + "}"}
    assert model.model.variables[steps[1].variable].initial == "07:00:00"


def test_a_two_key_hold_is_the_lock_and_single_holds_near_lock_are_not() -> None:
    manual = """
## Keys
- **CLOCK** — Hold 3 seconds to set the clock.
- **▲ ▼** — Change the value. Hold ▲ and ▼ together for 3 seconds: key lock on or off.
While the lock is on, LOCK is shown.
"""
    actions = ["press_clock", "hold_clock", "press_up", "press_down", "hold_up_and_down"]
    model = read_manual(manual, actions).model
    lock = next(f for f in model.features.values() if f[0].variable == "child_lock")
    assert lock[0].actions == ["hold_up_and_down"]


def test_holding_a_stepping_key_takes_no_list_of_values() -> None:
    manual = """
## Keys
- **TIMER** — Switches the start time on or off.
- **▲ ▼** — Change the value being set. Hold ▲ and ▼ together for 3 s: key lock.

## Start time
1. Press TIMER. The start time shows (06:00 the first time).
2. Press ▲ or ▼ to change the start time by 30 minutes per press.

Start time positions (30-minute steps):
  00:00  00:30  01:00  …  22:30  23:00  23:30
"""
    actions = ["press_timer", "press_up", "press_down", "hold_up", "hold_down", "hold_up_and_down"]
    model = read_manual(manual, actions).model
    for name, var in model.variables.items():
        assert "23:30" not in [str(v) for v in getattr(var, "values", None) or []], name
