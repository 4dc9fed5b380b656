"""Rules for what a converted PDF draws: cycles of lamps, rows of knob marks, counted positions."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.value_lists import find_list

FAN_HEATER = """
SAFETY FIRST
Never cover the heater. Keep curtains, furniture and bedding at least 1 m away from the
front grille. Do not use the heater in bathrooms or near a bath, shower or swimming pool.

PANEL
SETTING knob      Mains switch and heat setting.
OFF TIMER         Stops the heater after a while.

USE
The knob has five positions. It clicks into each one.

      OFF  ·  FAN  ·  LOW  ·  MID  ·  HIGH
      ---- turn right for more heat ---->

Turn the knob away from OFF to switch on.

Each press of OFF TIMER lights the next lamp:

   none  →  1H  →  3H  →  6H  →  none  →  …
"""

ACTIONS = ["turn_knob_cw", "turn_knob_ccw", "press_off_timer"]


def test_an_arrow_cycle_is_read_once_and_its_leading_none_is_zero() -> None:
    assert find_list("none → 1H → 3H → 6H → none → …") == (["0 H", "1 H", "3 H", "6 H"], "arrows")
    assert find_list("ECO → TURBO → QUIET → ECO") == (["ECO", "TURBO", "QUIET"], "arrows")


def test_the_counted_positions_of_the_one_knob_are_the_row_drawn_after() -> None:
    model = read_manual(FAN_HEATER, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    knob = next(v for v in model.variables.values() if v.label == "SETTING")
    assert knob.values == ["off", "fan", "low", "mid", "high"]


def test_the_timer_cycle_becomes_hours() -> None:
    model = read_manual(FAN_HEATER, ACTIONS).model
    timer = next(v for v in model.variables.values() if v.label == "OFF TIMER")
    assert timer.type == "numeric" and timer.unit == "h"
    assert timer.ranges[0][0] == 0 and timer.ranges[-1][1] == 6


WATER_POT = """
# Thermo pot TP-2

## Important safeguards
Do not carry the pot while it holds hot water. Do not operate it empty. Keep the cord away from
children. Unplug before cleaning.

## Panel

| No. | Key | What it does |
|---|---|---|
| 1 | TEMP SELECT | Picks the holding temperature. |
| 2 | SERVE SIZE | Picks how much one pour gives. |
| 3 | POUR | Pours. |

Keep-warm temperature lamps: **60 · 75 · 85 · 95 °C**
Serve-size lamps: **SMALL · LARGE · CARAFE**

## Holding temperature
Press **TEMP SELECT**; each press lights the next lamp.
"""


def test_field_lines_with_hyphenated_names_stay_apart_and_lamps_match_by_word_stem() -> None:
    model = read_manual(WATER_POT, ["press_temp", "press_serve_size", "press_pour"]).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    size = next(v for v in model.variables.values() if v.label == "SERVE SIZE")
    assert size.values == ["small", "large", "carafe"]
    temp = next(v for v in model.variables.values() if v.label == "TEMP SELECT")
    assert temp.type == "numeric" and temp.unit == "°C"  # a TEMP SELECT key sets an amount
    assert temp.ranges[0][0] == 60 and temp.ranges[-1][1] == 95


TEA_KETTLE = """
1 SAFETY
Use the kettle only with the base supplied. Never fill above MAX. Do not open the lid while
the water boils. Keep the appliance and its cord out of the reach of children under 8.

2 PARTS
A  Lid          B  Base          C  Heat dial (HEAT)          D  HOLD switch (0 / I)

3 USE
The heat dial has printed marks at 40, 60, 80 and 100 °C. Each click is one setting, 10 °C
apart (40, 50, 60 ... 90, 100), so the dots between the marks are 50, 70 and 90 °C.
Slide the HOLD switch to I to hold the water hot after boiling; back to 0 to stop.
"""


def test_an_ellipsis_run_of_numbers_gives_every_setting() -> None:
    actions = ["turn_heat_cw", "turn_heat_ccw", "slide_hold"]
    model = read_manual(TEA_KETTLE, actions).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    heat = next(v for v in model.variables.values() if v.label == "HEAT")
    assert heat.ranges == [(40, 100, 10)]


def test_a_switch_printed_0_and_i_is_off_and_on() -> None:
    model = read_manual(TEA_KETTLE, ["turn_heat_cw", "turn_heat_ccw", "slide_hold"]).model
    hold = next(v for v in model.variables.values() if v.label == "HOLD")
    assert hold.values == ["off", "on"]


TOASTER = """
IMPORTANT SAFEGUARDS
Do not touch hot surfaces; use handles or knobs. Unplug from outlet when not in use and before
cleaning. Allow to cool before putting on or taking off parts. Oversize foods must not be used.

USING THE CONTROLS

HEAT °F knob
Marked on the knob: 250 300 350 400 450. The knob clicks between the marks, so a temperature
halfway between two printed numbers can be set as well. Most foods bake at 350 °F.

TIME knob
The scale reads OFF 5 10 15 30 45 60 (minutes). In the first five minutes every minute has its
own click, for toast; above that it clicks at the printed marks only.
"""

TOASTER_ACTIONS = ["turn_heat_cw", "turn_heat_ccw", "turn_time_cw", "turn_time_ccw"]


def test_clicks_between_the_marks_add_the_midpoints_and_the_manual_speaks_fahrenheit() -> None:
    model = read_manual(TOASTER, TOASTER_ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    heat = next(v for v in model.variables.values() if v.label.startswith("HEAT"))
    assert heat.unit == "°F" and heat.ranges == [(250, 450, 25)]


def test_every_minute_in_the_first_few_minutes_has_its_own_setting() -> None:
    model = read_manual(TOASTER, TOASTER_ACTIONS).model
    time = next(v for v in model.variables.values() if v.label == "TIME")
    assert time.ranges[0] == ("00:00:00", "00:05:00", 60)


def test_an_arrow_list_of_amounts_keeps_the_first_amount_and_ends_before_and_then_back() -> None:
    found = find_list(
        "Each touch goes on in the order 0.5 LB → 1 LB → 1.5 LB and then back to 0.5 LB."
    )
    assert found == (["0.5 LB", "1 LB", "1.5 LB"], "arrows")
    found = find_list("Touch MODE to step through ECO → NORMAL → BOOST and back to ECO.")
    assert found == (["ECO", "NORMAL", "BOOST"], "arrows")


LEGEND = """
## Panel legend

 Symbol       Name            Function
 ──────────────────────────────────────────────
 BATCH        Batch size      0.5 LB, 1.0 LB, 1.5 LB
 GO           Start           Starts the programme
"""


def test_a_legend_row_lends_its_key_the_list_in_any_later_cell() -> None:
    model = read_manual(LEGEND, ["press_batch", "press_go"]).model
    batch = next(v for v in model.variables.values() if v.label == "BATCH")
    assert batch.unit == "lb" and batch.ranges == [(0.5, 1.5, 0.5)]


MAKER = """
## Display
The display shows the programme as MENU 1, MENU 2 … MENU 9, with the hours when a DELAY is set.

## Browning
Touch SHADE to change the browning: 1 (light) → 2 (medium) → 3 (dark) → back to 1.

## Delay
Touch DELAY. Each further touch adds one hour:
1, 2, 3 … up to 12 hours.
"""


def test_progressions_belong_to_the_key_they_name_and_arrow_cycles_end_at_back() -> None:
    model = read_manual(MAKER, ["press_menu", "press_shade", "press_delay"]).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    assert model.variables["menu"].values == [str(n) for n in range(1, 10)]
    shade = model.variables["shade"]  # 1–3 although MENU's codes hold 1, 2 and 3
    assert shade.type == "numeric" and shade.ranges == [(1, 3, 1)]
    delay = model.variables["delay"]
    assert delay.unit == "h" and delay.ranges[-1][1] == 12
