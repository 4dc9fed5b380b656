"""HOUR and MIN keys shared by the clock and a finish time, and what goes with them."""

from __future__ import annotations

from apbot.model.validate import check_model
from apbot.read import read_manual
from apbot.read.goal import parse_instruction
from apbot.read.value_steps import find_step

PORRIDGE_POT = """
SAFETY NOTES
Keep the steam vent clear. Never open the lid while the pot is under pressure. Do not let
children use the appliance. The outer body gets hot during cooking.

KEYS
| Key | Use |
|---|---|
| CLOCK | Opens the time of day for setting. |
| DONE BY | Switches the finish-time function on or off and shows the finish time. |
| HOUR | Moves the flashing time on by one hour. |
| MIN | Moves the flashing time on in minutes. |
| START | Starts. |

SETTING THE CLOCK
The clock runs on the 24-hour system. Press CLOCK, then HOUR and MIN; each MIN press adds one
minute.

FINISH TIME
Press DONE BY; the stored finish time shows. Use HOUR and MIN to move it to when the food
should be ready, then press START. Warm holding lasts up to 12 hours after cooking.

SPECIFICATIONS
| Finish-time function | up to 13 h ahead, fifteen-minute steps |
"""

ACTIONS = ["press_clock", "press_done_by", "press_hour", "press_min", "press_start"]


def test_hour_and_min_move_the_time_each_key_opens() -> None:
    model = read_manual(PORRIDGE_POT, ACTIONS).model
    assert not [p for p in check_model(model) if p.severity == "error"]
    clock = next(f for f in model.features.values() if f[0].actions == ["press_clock"])
    assert clock[1].actions == ["press_hour", "press_min"]
    assert model.variables[clock[1].variable].ranges[0] == ("00:00:00", "23:59:00", 60)
    finish = next(f for f in model.features.values() if f[0].actions == ["press_done_by"])
    spec = model.variables[finish[1].variable]
    assert spec.ranges[0][2] == 900  # the step the specifications give for the finish time
    assert finish[0].effect == "toggle"  # "switches the finish-time function on or off"


def test_twelve_hours_of_warm_holding_is_no_twelve_hour_clock() -> None:
    model = read_manual(PORRIDGE_POT, ACTIONS).model
    clock = next(f for f in model.features.values() if f[0].actions == ["press_clock"])
    assert model.variables[clock[1].variable].ranges[0][0] == "00:00:00"


def test_a_step_written_as_an_adjective_before_steps() -> None:
    assert find_step("up to 13 h ahead, fifteen-minute steps") == (15.0, "min")


def test_a_duration_no_word_claims_goes_to_the_cooking_time() -> None:
    oven = """
## Keys
- QUICK MIN — each press adds a minute and starts.
- Number keys 0-9 — enter the cooking time; no key is needed first.
- START — starts.
"""
    actions = ["press_quick_min", "press_start"] + [f"press_{d}" for d in range(10)]
    model = read_manual(oven, actions).model
    goal = parse_instruction(model, "Heat the soup for 4 minutes and start.")
    assert goal.get("cook_time") == "00:04:00", goal


def test_a_key_whose_legend_says_it_takes_the_cooking_time_is_the_cooking_time() -> None:
    hob = """
## Keys
* **HEAT** — the keypad then takes the power level.
* **TIMER** — the keypad then takes the cooking time in minutes.
* **0 – 9** — number keys.
"""
    actions = ["press_heat", "press_timer"] + [f"press_{d}" for d in range(10)]
    model = read_manual(hob, actions).model
    times = [n for n, v in model.variables.items() if v.type == "time"]
    assert times == ["timer"], times  # no second cooking time the digits set alone


def test_a_cooking_time_typed_straight_away_stays_beside_a_minute_minder() -> None:
    oven = """
## Keys
- **Number pads 0–9**: type a cooking time straight away, or a value after TIMER.
- **TIMER**: minute minder (no heating).
"""
    actions = ["press_timer"] + [f"press_{d}" for d in range(10)]
    model = read_manual(oven, actions).model
    times = sorted(n for n, v in model.variables.items() if v.type == "time")
    assert times == ["cook_time", "timer"], times
